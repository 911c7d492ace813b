// The closed-form response of one linear degree of freedom, M q'' + C q' + K q = F(t), from
// its initial conditions: the regime and its free solutions, the forced part, the constants,
// the check in the equation of motion, and how long the response holds where a rule assumes
// the direction of motion.
#include "motion/motion_detail.hpp"

#include <cmath>
#include <random>
#include <string>

#include <fmt/format.h>

#include "expr/normal_form.hpp"
#include "expr/print.hpp"
#include "expr/rational.hpp"
#include "numeric/compiled.hpp"

namespace tackle::motion_detail {

using namespace GiNaC;

namespace {

// A forcing F(t) = F0 + A cos(w t) + B sin(w t) (one frequency), when it has that form.
struct Forcing {
  ex constant = 0, a = 0, b = 0, w = 0;
};

std::optional<Forcing> harmonic(const ex& F, const ex& t) {
  Forcing f;
  const ex e = F.expand();
  const std::size_t n = is_a<add>(e) ? e.nops() : 1;
  for (std::size_t i = 0; i < n; ++i) {
    const ex term = is_a<add>(e) ? e.op(i) : e;
    if (!term.has(t)) {
      f.constant += term;
      continue;
    }
    // term = coefficient * cos(w t) or * sin(w t)
    ex fn, coeff = 1;
    const std::size_t k = is_a<mul>(term) ? term.nops() : 1;
    for (std::size_t j = 0; j < k; ++j) {
      const ex factor = is_a<mul>(term) ? term.op(j) : term;
      if (!factor.has(t)) {
        coeff *= factor;
      } else if (fn.is_zero() && (is_ex_the_function(factor, cos) || is_ex_the_function(factor, sin))) {
        fn = factor;
      } else {
        return std::nullopt;
      }
    }
    const ex arg = fn.op(0).expand();
    const ex w = arg.diff(ex_to<symbol>(t));
    if (w.has(t) || !zero(arg.subs(t == 0))) return std::nullopt;
    if (!f.w.is_zero() && !zero(f.w - w)) return std::nullopt;  // two frequencies
    f.w = w;
    (is_ex_the_function(fn, cos) ? f.a : f.b) += coeff;
  }
  return f;
}

// Random positive rational values for the parameters, and the definitions put in.
exmap random_point(const SymbolTable& table, std::mt19937& rng) {
  std::uniform_int_distribution<int> num(1, 40), den(1, 9);
  exmap p;
  for (const auto& s : table.all())
    if (s->role == SymbolRole::parameter && !s->definition && !s->geometric) p[s->sym] = numeric(num(rng), den(rng));
  return p;
}

// How long the response holds when a rule assumes the direction of motion: until the rate
// first vanishes. From rest an oscillation turns after half a period (pi/lambda, pi/omega_d);
// otherwise the rate is followed with the numbers (a scan, then bisection).
void sliding_interval(Motion& out, const Model& m, const MotionSpec& spec) {
  const Response& r = *out.response;
  out.direction_assumed_by = m.direction_assumed_by;
  const bool from_rest = zero(spec.initial.at(out.eom.dq[0]));
  if (from_rest && r.regime == Response::Regime::undamped) out.direction_until = Pi / spec.lambda;
  if (from_rest && r.regime == Response::Regime::underdamped) out.direction_until = Pi / spec.omega_d;
  exmap values = m.symbols->values();
  for (const auto& [sym, def] : out.definitions) values[sym] = substituted(substituted(def, values), values);
  // The rate in time alone, compiled for doubles: the scan below evaluates it thousands of
  // times, and each exact substitution cost 30 million instructions on a driven slope.
  // (Not compiled, a symbol or function it cannot evaluate: each time exactly.)
  std::string problem;
  const auto compiled = Compiled::compile(evalf(substituted(r.rate, values)), {m.time}, problem);
  const NormalForm exact_rate(r.rate);
  auto rate_at = [&](double time) -> std::optional<double> {
    if (compiled && time != 0) {  // (at the start exactly: a rest is 0, not a rounding)
      const double v = (*compiled)(&time);
      return std::isfinite(v) ? std::optional<double>(v) : std::nullopt;
    }
    exmap at = values;
    at[m.time] = numeric(time);
    return exact_rate.approx_at(at);
  };
  if (out.direction_until) {
    if (auto v = NormalForm(*out.direction_until).approx_at(values))
      out.direction_until_s = *v;
    else
      out.direction_unknown = true;
    return;
  }
  // The first sign change within the run's end (or 100 s), on a grid of 4000 steps.
  const double horizon = spec.until ? ex_to<numeric>(evalf(*spec.until)).to_double() : 100.0;
  const int steps = 4000;
  std::optional<double> previous = rate_at(0);
  if (!previous) {
    out.direction_unknown = true;
    return;
  }
  double start_sign = *previous;
  for (int i = 1; i <= steps; ++i) {
    const double t1 = horizon * i / steps;
    const auto v = rate_at(t1);
    if (!v) {
      out.direction_unknown = true;
      return;
    }
    if (start_sign == 0)
      start_sign = *v;  // from rest: the sign it takes
    else if ((*v > 0) != (start_sign > 0) || *v == 0) {
      double lo = horizon * (i - 1) / steps, hi = t1;
      for (int k = 0; k < 60; ++k) {
        const double mid = (lo + hi) / 2;
        const auto w = rate_at(mid);
        if (!w) break;
        ((*w > 0) == (start_sign > 0) && *w != 0 ? lo : hi) = mid;
      }
      // To 12 significant digits: the rate's compiled form sums in GiNaC's order, which
      // follows the run's addresses, and its last bits (so the bisection's last step) with it.
      out.direction_until_s = std::stod(fmt::format("{:.12g}", hi));
      return;
    }
  }
  out.direction_kept = true;
}

// The sign of `e`: from the algebra, else with the parameters' values; nothing when neither tells.
std::optional<int> numeric_sign(const ex& e, const exmap& values) {
  if (auto sg = sign_of(normal(e))) return sg;
  if (auto v = NormalForm(e).approx_at(values)) return *v > 0 ? 1 : (*v < 0 ? -1 : 0);
  return std::nullopt;
}

// The equation M q'' + C q' + K q = F(t) of one degree of freedom, and the response that the
// steps below make from it in turn.
struct ResponseMaking {
  ex M, C, K;
  Forcing forcing{};
  exmap values{};  // the parameters' values, for a sign the algebra does not tell
  bool undamped = false, unsprung = false;
  Response r{};
  ex h1{}, h2{};  // the free solutions of the regime
  ex qp = 0;      // the forced part
  bool resonant = false;
};

// The regime, from the damping and the stiffness: its free solutions h1, h2 and the
// quantities they are written in (lambda, zeta, omega_d).
void free_solutions(ResponseMaking& rm, const MotionSpec& spec, const ex& t) {
  Response& r = rm.r;
  const ex &M = rm.M, &C = rm.C, &K = rm.K;
  ex &h1 = rm.h1, &h2 = rm.h2;
  const ex& lambda = spec.lambda;
  const ex& zeta = spec.zeta;
  const ex& wd = spec.omega_d;
  rm.undamped = zero(C);
  rm.unsprung = zero(K);
  const bool undamped = rm.undamped, unsprung = rm.unsprung;
  if (undamped && unsprung) {
    r.regime = Response::Regime::free_particle;
    h1 = 1;
    h2 = t;
  } else if (undamped) {
    r.regime = Response::Regime::undamped;
    r.definitions.emplace_back(lambda, sqrt(simplest(K / M)));
    h1 = cos(lambda * t);
    h2 = sin(lambda * t);
  } else if (unsprung) {
    r.regime = Response::Regime::damped_particle;
    h1 = 1;
    h2 = exp(-simplest(C / M) * t);
  } else {
    r.definitions.emplace_back(lambda, sqrt(simplest(K / M)));
    r.definitions.emplace_back(zeta, simplest(C / (2 * sqrt(K * M))));
    const ex disc = normal(C * C - 4 * K * M);
    const auto sg = zero(disc) ? std::optional<int>(0) : numeric_sign(disc, rm.values);
    // The decay rate zeta*lambda = C/(2 M) and the damped frequency are written in the
    // parameters directly (GiNaC does not see sqrt(k/m)*c/(2*sqrt(k*m)) = c/(2*m)).
    const ex decay = simplest(C / (2 * M));
    if (sg == 0) {
      r.regime = Response::Regime::critically_damped;
      h1 = exp(-decay * t);
      h2 = t * exp(-decay * t);
    } else if (sg == 1) {
      r.regime = Response::Regime::overdamped;
      r.definitions.emplace_back(wd, sqrt(simplest(pow(C / (2 * M), 2) - K / M)));
      h1 = exp(-decay * t) * cosh(wd * t);
      h2 = exp(-decay * t) * sinh(wd * t);
    } else {
      r.regime = Response::Regime::underdamped;
      if (!sg) r.assumptions.push_back({zeta, 1, "<", "underdamped"});
      r.definitions.emplace_back(wd, sqrt(simplest(K / M - pow(C / (2 * M), 2))));
      h1 = exp(-decay * t) * cos(wd * t);
      h2 = exp(-decay * t) * sin(wd * t);
    }
  }
}

// The forced part qp: the constant forcing's (F0/K, or a drift where there is no spring) plus
// the harmonic forcing's X cos(w t) + Y sin(w t); none at the natural frequency (resonance).
void forced_part(ResponseMaking& rm, Motion& out, const ex& lambda, const ex& t) {
  const ex &M = rm.M, &C = rm.C, &K = rm.K;
  const Forcing& forcing = rm.forcing;
  ex& qp = rm.qp;
  const ex F0 = forcing.constant;
  if (!zero(F0)) qp += simplest(!rm.unsprung ? F0 / K : (!rm.undamped ? F0 * t / C : F0 * pow(t, 2) / (2 * M)));
  if (!zero(forcing.a) || !zero(forcing.b)) {
    const ex w = forcing.w;
    const ex k = K - M * pow(w, 2), c = C * w;
    const ex det = normal(k * k + c * c);
    if (det.is_zero()) {
      rm.resonant = true;
      out.no_response = "the forcing is at the natural frequency (resonance; simulate it)";
    } else {
      const ex X = simplest((k * forcing.a - c * forcing.b) / det);
      const ex Y = simplest((c * forcing.a + k * forcing.b) / det);
      qp += X * cos(w * t) + Y * sin(w * t);
      if (rm.undamped) rm.r.assumptions.push_back({w, lambda, "!=", "no resonance"});
      rm.r.forcing_frequency = w;
    }
  }
}

// The constants of the free part from q(0) = q0, dot(q)(0) = v0: the response q(t) and its
// rate, and the response's definitions kept for the numbers.
void fit_initial_conditions(ResponseMaking& rm, MotionStory& st, const ex& t) {
  Response& r = rm.r;
  const ex &qp = rm.qp, &h1 = rm.h1, &h2 = rm.h2;
  const symbol a("a"), b("b");
  const ex trial = qp + a * h1 + b * h2;
  const ex q0 = st.spec.initial.at(st.eom.q[0]), v0 = st.spec.initial.at(st.eom.dq[0]);
  const ex eq1 = trial.subs(t == 0) - q0;
  const ex eq2 = trial.diff(ex_to<symbol>(t)).subs(t == 0) - v0;
  const ex sol2 = lsolve(lst{eq1 == 0, eq2 == 0}, lst{a, b});
  ex av = 0, bv = 0;
  for (const auto& rel : sol2) {
    if (rel.lhs().is_equal(a)) av = simplest(rel.rhs());
    if (rel.lhs().is_equal(b)) bv = simplest(rel.rhs());
  }
  r.particular = qp;
  r.homogeneous = av * h1 + bv * h2;
  r.q = qp + r.homogeneous;
  r.rate = r.q.diff(ex_to<symbol>(t));
  for (const auto& [sym, def] : r.definitions) st.out.definitions[sym] = def;
}

// Verified: M q'' + C q' + K q - F(t) at random parameter values and times. The defined
// parameters (every geometric length too) and the response's own definitions are put in
// first, so that the residual and its scale are in the free parameters and t only; both are
// compiled once and evaluated in doubles.
bool verified(const ResponseMaking& rm, const EquationsOfMotion& eom, const SymbolTable& table, const ex& t) {
  const Response& r = rm.r;
  const ex &M = rm.M, &C = rm.C, &K = rm.K;
  exmap defs = table.definitions(true);
  for (const auto& [sym, def] : r.definitions) defs[sym] = def;
  for (int depth = 0; depth < 8; ++depth)
    for (auto& [k, v] : defs) v = substituted(v, defs);
  const ex acceleration = r.q.diff(ex_to<symbol>(t), 2);
  const ex residual = substituted(M * acceleration + C * r.rate + K * r.q - eom.forcing[0], defs);
  const ex scale_of = substituted(abs(M * acceleration) + abs(K * r.q) + abs(eom.forcing[0]) + 1, defs);
  std::vector<ex> inputs{t};
  for (const ex& x : symbols_in(residual + scale_of))
    if (!x.is_equal(t)) inputs.push_back(x);
  std::string problem;
  const auto residual_at = Compiled::compile(residual, inputs, problem);
  const auto scale_at = Compiled::compile(scale_of, inputs, problem);
  std::mt19937 rng(11);
  bool ok = residual_at && scale_at;
  int checked = 0;
  for (int trial_no = 0; trial_no < 4 && ok; ++trial_no) {
    const exmap p = random_point(table, rng);
    std::vector<double> x(inputs.size());
    bool valued = true;
    for (std::size_t i = 1; i < inputs.size() && valued; ++i) {
      const auto it = p.find(inputs[i]);
      if (it == p.end())
        valued = false;
      else
        x[i] = ex_to<numeric>(it->second).to_double();
    }
    if (!valued) continue;
    for (const double tt : {0.0, 0.37, 1.9}) {
      x[0] = tt;
      const double v = (*residual_at)(x.data()), scale = (*scale_at)(x.data());
      if (!std::isfinite(v) || !std::isfinite(scale)) continue;  // a damping regime that does not hold at this point
      ++checked;
      if (std::abs(v) > 1e-8 * scale) ok = false;
    }
  }
  return ok && checked > 0;
}

}  // namespace

void closed_form_response(MotionStory& st) {
  const EquationsOfMotion& eom = st.eom;
  const ex& t = st.m.time;
  ResponseMaking rm{eom.M(0, 0), eom.C(0, 0), eom.K(0, 0)};
  const auto forcing = harmonic(eom.forcing[0], t);
  rm.values = st.table.values();
  if (!forcing) {
    st.out.no_response =
        "the forcing " + to_text(eom.forcing[0]) + " is not a constant plus one harmonic term (simulate it)";
    return;
  }
  if (!zero(rm.K) && numeric_sign(rm.K / rm.M, rm.values) != std::optional<int>(1)) {
    st.out.no_response = "the stiffness " + to_text(rm.K) + " is not known to be positive";
    return;
  }
  rm.forcing = *forcing;
  free_solutions(rm, st.spec, t);
  forced_part(rm, st.out, st.spec.lambda, t);
  if (rm.resonant) return;
  fit_initial_conditions(rm, st, t);
  rm.r.verified = verified(rm, eom, st.table, t);
  st.out.response = std::move(rm.r);
  if (!st.m.direction_assumed_by.empty()) sliding_interval(st.out, st.m, st.spec);
}

}  // namespace tackle::motion_detail
