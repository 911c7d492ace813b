#include "motion/motion.hpp"

#include "motion/mass_form.hpp"

#include <algorithm>
#include <cmath>
#include <random>
#include <tuple>

#include <Eigen/Dense>

#include "expr/normal_form.hpp"
#include "expr/print.hpp"
#include "expr/rational.hpp"
#include "model/kinematics.hpp"
#include "numeric/compiled.hpp"

namespace tackle {

using namespace GiNaC;

namespace {

bool zero(const ex& e) { return normal(e).is_zero(); }

// The parameters of the problem, for solving conditions.
std::vector<ex> parameters_of(const SymbolTable& t) {
  std::vector<ex> out;
  for (const auto& s : t.all())
    if (s->role == SymbolRole::parameter && !s->geometric) out.push_back(s->sym);
  return out;
}

// Everything that varies with the state: the coordinates, the rates and the turning lengths.
bool depends_on_state(const ex& e, const std::vector<ex>& state, const Model& m) {
  for (const auto& s : state)
    if (e.has(s)) return true;
  for (const auto& l : m.lengths)
    if (e.has(l.symbol)) return true;
  return false;
}

// The dependent coordinates and rates in terms of the independent ones: rates from the
// constraints' rate equations, coordinates from the constraint quantities keeping their
// values at t = 0 (which needs those coordinates' initial values).
struct Dependents {
  exmap rates, coords;
  exmap definitions;  // the defined parameters (y_s = (m + M) g/k), put in so that terms cancel
  std::string problem;
};

// A massless body's coordinate that its balance fixes: its value from the solve, in the
// state, and its rate by the chain rule.
void add_balance_coordinates(Dependents& d, const Model& m, const Solution& sol) {
  for (const auto& q : balance_coordinates(m)) {
    const auto v = sol.value_of(q);
    if (!v) continue;  // the solve did not give it: what needs it says so
    const ex value = d.coords.empty() ? *v : substituted(*v, d.coords);
    d.coords[q] = value;
    const auto body = std::find_if(m.bodies.begin(), m.bodies.end(), [&](const Body& b) { return b.coord.is_equal(q); });
    ex rate = time_derivative(value, m);
    if (!d.rates.empty()) rate = substituted(rate, d.rates);
    d.rates[body->rate] = rate;
  }
}

Dependents dependents(const Model& m, const EquationSystem& s, const Solution& sol, const MotionSpec& spec, const ex& needed) {
  Dependents d;
  d.definitions = m.symbols->definitions();
  const std::vector<ex> by_balance = balance_coordinates(m);
  std::vector<ex> dep_rates, dep_coords;
  for (const auto& c : m.coordinates) {
    if (contains(by_balance, c.q) || contains(spec.coordinates, c.q)) continue;
    dep_rates.push_back(c.rate);
    dep_coords.push_back(c.q);
  }
  if (!dep_rates.empty() && !s.rate_equations.empty()) {
    const Solution r = solve_equations(m.file, s.rate_equations, dep_rates);
    for (const auto& v : r.values) d.rates[v.unknown] = v.value;
  }
  // A dependent coordinate is needed where it appears, also inside a strand's length that
  // turns with it (l_RG = sqrt(L^2 + (H + y_R)^2) in a force on a massless ring).
  bool coords_needed = false;
  for (const auto& c : dep_coords) {
    coords_needed = coords_needed || needed.has(c);
    for (const auto& l : m.lengths) coords_needed = coords_needed || (needed.has(l.symbol) && l.squared.has(c));
  }
  if (!coords_needed) {
    add_balance_coordinates(d, m, sol);
    return d;
  }
  // quantity(q) = quantity(q at t = 0) for each constraint. An initial value 'initial' does
  // not give stands as a symbol of its own: it often cancels (a fixed pulley's height in the
  // length of the string over it), and where it does not, that value is what is missing.
  exmap at_start = spec.initial;
  std::vector<std::pair<ex, ex>> not_given;  // (symbol standing for q(0), q)
  for (const auto& c : m.coordinates)
    if (!spec.initial.count(c.q)) {
      const symbol q0(to_text(c.q) + "(0)");
      at_start[c.q] = q0;
      not_given.emplace_back(q0, c.q);
    }
  std::vector<Equation> eqs;
  for (const auto& c : m.constraints) {
    Equation e;
    e.kind = Equation::Kind::constraint_position;
    e.label = c.label;
    e.lhs = c.quantity;
    e.rhs = substituted(c.quantity, at_start);
    eqs.push_back(e);
  }
  const Solution r = solve_equations(m.file, eqs, dep_coords);
  for (const auto& v : r.values) d.coords[v.unknown] = v.value;
  // The dependent coordinates that are needed, and the starting values they still contain.
  std::vector<std::string> missing;
  for (const auto& c : dep_coords) {
    bool used = needed.has(c);
    for (const auto& l : m.lengths) used = used || (needed.has(l.symbol) && l.squared.has(c));
    if (!used) continue;
    const auto it = d.coords.find(c);
    if (it == d.coords.end()) {  // not solved for: reported where it is used, unless it is missing
      if (!spec.initial.count(c) && std::find(missing.begin(), missing.end(), to_text(c)) == missing.end()) missing.push_back(to_text(c));
      continue;
    }
    for (const auto& [q0, q] : not_given)
      if (it->second.has(q0) && std::find(missing.begin(), missing.end(), to_text(q)) == missing.end()) missing.push_back(to_text(q));
  }
  if (!missing.empty()) {
    d.problem = "the motion needs the initial value of " + join(missing, " and ") +
                " (the constraints fix " + (missing.size() == 1 ? "it" : "them") + " only up to a constant; expected " +
                (missing.size() == 1 ? "it" : "them") + " in 'initial')";
    return d;
  }
  // A coordinate that is not needed and whose place depends on a starting value not given
  // is not placed (what uses it later says that it cannot be followed).
  for (auto it = d.coords.begin(); it != d.coords.end();)
    if (std::any_of(not_given.begin(), not_given.end(), [&](const auto& p) { return it->second.has(p.first); }))
      it = d.coords.erase(it);
    else
      ++it;
  add_balance_coordinates(d, m, sol);
  return d;
}

ex put_in(const ex& e, const Dependents& d) {
  ex out = e;
  for (int depth = 0; depth < 8; ++depth) out = substituted(out, d.definitions);
  if (!d.coords.empty()) out = substituted(out, d.coords);
  if (!d.rates.empty()) out = substituted(out, d.rates);
  return out;
}

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

// 1/2 M v^2 = 1/2 M v0^2 + the work of Q(q) = M f(q) from q0 to q1: in closed form when GiNaC
// integrates Q (a polynomial in q), else by Gauss-Legendre quadrature with the given values.
EnergyAnswer work_energy(const Model& m, const EquationsOfMotion& eom, const MotionSpec& spec, bool mass_constant) {
  EnergyAnswer e;
  e.position = spec.speed_at->second;
  const ex& q = eom.q[0];
  const ex f = eom.acceleration[0];
  if (!mass_constant) {
    e.not_possible = "the kinetic energy's coefficient changes with the coordinate";
    return e;
  }
  if (f.has(eom.dq[0]) || f.has(m.time)) {
    e.not_possible = std::string("the forces depend on the ") + (f.has(m.time) ? "time" : "velocity (a damper)") +
                     ", so their work depends on the motion, not only on the positions (simulate it)";
    return e;
  }
  const SymbolTable& table = *m.symbols;
  const ex M = eom.M(0, 0);
  const ex q0 = spec.initial.at(q), v0 = spec.initial.at(eom.dq[0]), q1 = e.position;
  ex Q = normal(M * f);
  const bool geometric = std::any_of(m.lengths.begin(), m.lengths.end(), [&](const TurningLength& l) { return Q.has(l.symbol); });
  if (!geometric && Q.is_polynomial(q)) {
    const symbol s("s");
    const ex W = integral(s, q0, q1, Q.subs(q == s)).eval_integ();
    if (!is_a<integral>(W)) {
      e.work = simplest(W);
      e.rate_squared = simplest(pow(v0, 2) + 2 * e.work / M);
      if (auto v = NormalForm(*e.rate_squared).approx_at(table.values())) e.rate_squared_number = *v;
      return e;
    }
  }
  // Numerically: the turning lengths' definitions and the values put in, 64-point Gauss-Legendre.
  e.numeric_only = true;
  ex Qn = Q;
  const exmap defs = table.definitions(true);
  for (int depth = 0; depth < 8; ++depth) Qn = substituted(Qn, defs);
  const exmap values = table.values();
  exmap without_q = values;
  without_q.erase(q);
  Qn = substituted(Qn, without_q);
  const auto a = NormalForm(q0).approx_at(values), b = NormalForm(q1).approx_at(values), mv = NormalForm(M).approx_at(values),
             v0n = NormalForm(v0).approx_at(values);
  if (!a || !b || !mv || !v0n) {
    e.not_possible = "the work has no closed form and some value is missing for a number";
    return e;
  }
  std::string problem;
  const auto Qc = Compiled::compile(Qn, {q}, problem);
  if (!Qc) {
    e.not_possible = "the work has no closed form and " + problem;
    return e;
  }
  // Composite Gauss-Legendre (5 points on each of 64 panels).
  static const double x5[] = {0, -0.5384693101056831, 0.5384693101056831, -0.9061798459386640, 0.9061798459386640};
  static const double w5[] = {0.5688888888888889, 0.4786286704993665, 0.4786286704993665, 0.2369268850561891, 0.2369268850561891};
  double W = 0;
  const int panels = 64;
  const double h = (*b - *a) / panels;
  for (int p = 0; p < panels; ++p) {
    const double mid = *a + (p + 0.5) * h;
    for (int k = 0; k < 5; ++k) {
      const double x = mid + x5[k] * h / 2;
      W += w5[k] * (*Qc)(&x) * h / 2;
    }
  }
  e.rate_squared_number = *v0n * *v0n + 2 * W / *mv;
  return e;
}

// `g` as alpha + beta cos(w t) + gamma sin(w t), each part free of t (nothing when it is not
// one). Where `g` is affine in the cosine and the sine as written (its derivatives in them
// free of both), each part is put over one denominator alone: normal() of the whole, with
// the particular solution's coefficients over theirs, was most of a driven slope's run.
std::tuple<std::optional<ex>, std::optional<ex>, std::optional<ex>> harmonic_parts(const ex& g, const ex& cos_wt, const ex& sin_wt,
                                                                                 const ex& t) {
  const symbol cs("cs"), sn("sn");
  const ex in_cs = g.subs(lst{cos_wt == cs, sin_wt == sn});
  const ex d_cs = in_cs.diff(cs), d_sn = in_cs.diff(sn);
  if (!d_cs.has(cs) && !d_cs.has(sn) && !d_sn.has(cs) && !d_sn.has(sn)) {
    const ex alpha = normal(in_cs.subs(lst{cs == 0, sn == 0})), beta = normal(d_cs), gamma = normal(d_sn);
    if (alpha.has(t) || beta.has(t) || gamma.has(t)) return {};
    return {alpha, beta, gamma};
  }
  const ex p = normal(g).subs(lst{cos_wt == cs, sin_wt == sn}).expand();
  if (p.has(t) || !p.is_polynomial(lst{cs, sn}) || p.degree(cs) > 1 || p.degree(sn) > 1 || p.coeff(cs, 1).has(sn)) return {};
  return {p.subs(lst{cs == 0, sn == 0}), p.coeff(cs, 1), p.coeff(sn, 1)};
}

// The condition in the steady state: along the forced part alone (see ConditionInTime).
// `in_state` is the condition in the motion's coordinate and rate, the dependent ones put in
// (a string's T = k (y_S + H - l_0) through the ring's y_S = x_0 + y_0 - x): a dependent
// coordinate left in would be held at no value, and its square read as a condition that
// always holds.
void steady_state(ConditionInTime& ct, const CheckedCondition& c, const ex& in_state, const Response& r,
                  const EquationsOfMotion& eom, const Model& m, const exmap& values) {
  const ex& t = m.time;
  const ex w = r.forcing_frequency;
  const ex qp = r.particular;
  const ex g = substituted(substituted(in_state, m.symbols->definitions()), exmap{{eom.q[0], qp}, {eom.dq[0], qp.diff(ex_to<symbol>(t))}});
  const auto [alpha0, beta0, gamma0] = harmonic_parts(g, cos(w * t), sin(w * t), t);
  if (!alpha0) return;
  const ex alpha = simplest(*alpha0), beta = simplest(*beta0), gamma = simplest(*gamma0);
  const std::string& op = c.condition->op;
  const bool lower = op == ">=" || op == ">";
  ct.steady_of_t = simplest(g);
  ct.steady_offset = alpha;
  // alpha^2 - beta^2 - gamma^2 over a denominator that is a square (positive): its numerator.
  const ex diff = normal(alpha * alpha - beta * beta - gamma * gamma);
  const ex num = diff.numer_denom().op(0), den = diff.numer_denom().op(1);
  // Positive: each factor an even power or of positive sign ((k - m w^2)^2, expanded by normal()).
  const ex fden = factor(den);
  bool positive = true;
  for (std::size_t i = 0, nfd = is_a<mul>(fden) ? fden.nops() : 1; i < nfd; ++i) {
    const ex fi = is_a<mul>(fden) ? fden.op(i) : fden;
    const bool even = is_a<power>(fi) && fi.op(1).info(info_flags::even);
    if (!even && sign_of(fi) != std::optional<int>(1)) positive = false;
  }
  if (!positive) return;
  // Undamped: alpha^2 - beta^2 = (alpha - beta)(alpha + beta), and the numerator's factors
  // are theirs (factor() of the whole numerator was half the run).
  ct.steady_amplitude_condition =
      gamma.is_zero() ? simplest_of_product(num, {numer_denom_remembered(alpha - beta).op(0), numer_denom_remembered(alpha + beta).op(0)})
                      : simplest(num);
  if (const auto v = NormalForm(lower ? alpha - sqrt(beta * beta + gamma * gamma) : alpha + sqrt(beta * beta + gamma * gamma)).approx_at(values))
    ct.steady_holds = lower ? (op == ">=" ? *v >= 0 : *v > 0) : (op == "<=" ? *v <= 0 : *v < 0);
  // In w^2: a quadratic with two roots gives the band.
  if (!is_a<symbol>(w)) return;
  const symbol W("W");
  const ex inW = num.expand().subs(pow(w, 2) == W, subs_options::algebraic).expand();
  if (inW.has(w) || !inW.is_polynomial(W) || inW.degree(W) != 2) return;
  const ex A = inW.coeff(W, 2);
  // Roots from the factors when it factors into two linear ones, else none (a root of a
  // discriminant is not what a person writes for this). The factors are those of the
  // amplitude condition, made above, in W, when each factor with w in it is a polynomial in
  // w^2; else factor() of the quadratic (the same polynomial factored twice was 40 % of the
  // run).
  const auto in_W = [&](const ex& x) {
    const ex y = x.expand().subs(pow(w, 2) == W, subs_options::algebraic).expand();
    return y.has(w) ? std::optional<ex>() : std::optional<ex>(y);
  };
  std::optional<ex> reused;
  if (const ex& made = *ct.steady_amplitude_condition; is_a<mul>(made)) {
    ex product = 1;
    bool all = true;
    for (const ex& fi : made) {
      const bool powered = is_a<power>(fi);
      const auto base = in_W(powered ? fi.op(0) : fi);
      all = all && base;
      if (base) product *= powered ? pow(*base, fi.op(1)) : *base;
    }
    if (all) reused = product;
  }
  const ex f = reused ? *reused : factor(inW);
  std::vector<ex> roots;
  const std::size_t nf = is_a<mul>(f) ? f.nops() : 1;
  for (std::size_t i = 0; i < nf; ++i) {
    const ex fi = is_a<mul>(f) ? f.op(i) : f;
    if (!fi.has(W)) continue;
    if (is_a<power>(fi) && fi.op(1).is_equal(2) && fi.op(0).degree(W) == 1) {
      roots.push_back(simplest(-fi.op(0).coeff(W, 0) / fi.op(0).coeff(W, 1)));
      roots.push_back(roots.back());
    } else if (fi.degree(W) == 1) {
      roots.push_back(simplest(-fi.coeff(W, 0) / fi.coeff(W, 1)));
    }
  }
  if (roots.size() != 2) return;
  const auto r0 = NormalForm(roots[0]).approx_at(values), r1 = NormalForm(roots[1]).approx_at(values);
  const auto a_sign = NormalForm(A).approx_at(values);
  // Two positive roots make a band of w^2; a root at or below 0 leaves a half-line, which the
  // amplitude condition already says.
  if (!r0 || !r1 || !a_sign || *r0 <= 0 || *r1 <= 0) return;
  ConditionInTime::Band band;
  band.variable = pow(w, 2);
  band.low = *r0 <= *r1 ? roots[0] : roots[1];
  band.high = *r0 <= *r1 ? roots[1] : roots[0];
  // The quadratic is negative between its roots when its leading coefficient is positive.
  band.fails_between = *a_sign > 0;
  ct.band = band;
}

// Whether the motion starts against the direction a rule assumes (sliding friction that
// opposes the sliding): then the friction's power at t = 0 is positive (it would push along
// the motion), or, from rest, the power's first change is (the forces start the body the
// other way). Said in words; empty when the start agrees or the numbers cannot tell.
std::string against_at_start(const Model& m, const Solution& sol, const Dependents& dep, const MotionSpec& spec) {
  const exmap values = m.symbols->values();
  auto number = [&](const ex& e) -> std::optional<double> {
    ex v = put_in(substituted(e, sol.general), dep);
    v = substituted(v, spec.initial);
    for (int depth = 0; depth < 4; ++depth) v = substituted(substituted(v, dep.definitions), values);
    if (is_a<symbol>(m.time)) v = v.subs(m.time == 0);  // at the start (a support driven in time)
    v = evalf(v);
    if (!is_a<numeric>(v) || !ex_to<numeric>(v).is_real()) return std::nullopt;
    return ex_to<numeric>(v).to_double();
  };
  // A slip between two bodies: its relative speed against the assumed direction.
  for (const auto& s : m.slips) {
    if (s.bodies.size() < 2) continue;
    const auto v = number(s.speed);
    if (v && *v < -1e-9) return "at t = 0 the contact of " + s.source + " slips against the direction it assumes (its friction would push the bodies along, not hold them back)";
  }
  for (const auto& l : m.loads) {
    if (l.body < 0 || std::find(m.direction_assumed_by.begin(), m.direction_assumed_by.end(), l.source) == m.direction_assumed_by.end()) continue;
    // (Between two bodies, the relative slip above decides, not each body's own motion.)
    if (std::any_of(m.slips.begin(), m.slips.end(), [&](const Model::Slip& s) { return s.source == l.source && s.bodies.size() > 1; })) continue;
    const Body& b = m.bodies[static_cast<std::size_t>(l.body)];
    // The velocity of the point the friction acts at: the center's, unless the body turns.
    const bool turning = !b.angle.is_zero() && l.at;
    const auto velocity = turning ? kinematics::point_velocity(m, b, *l.at - b.cm) : kinematics::velocity(m, b);
    if (!velocity) continue;
    Vec acceleration = b.acceleration;
    if (turning)
      for (int k = 0; k < 3; ++k) acceleration[k] = time_derivative((*velocity)[k], m);
    double fv = 0, fa = 0, ff = 0, vv = 0, aa = 0;
    for (int k = 0; k < m.dims(); ++k) {
      const auto f = number(l.force[k]);
      const auto v = number((*velocity)[k]);
      const auto a = number(acceleration[k]);
      if (!f || !v || !a) return {};
      fv += *f * *v, fa += *f * *a, ff += *f * *f, vv += *v * *v, aa += *a * *a;
    }
    const double tiny = 1e-9;
    if (ff == 0) continue;
    if (vv > tiny * tiny && fv > tiny * std::sqrt(ff * vv))
      return "at t = 0 body '" + b.name + "' moves against the sliding direction that " + l.source +
             " assumes (its friction would push it along, not hold it back)";
    if (vv <= tiny * tiny && aa > tiny * tiny && fa > tiny * std::sqrt(ff * aa))
      return "from rest, the forces start body '" + b.name + "' against the sliding direction that " + l.source +
             " assumes (its friction would push it along, not hold it back)";
  }
  return {};
}

// Small oscillations of several nonlinear degrees of freedom about q = 0 where every one can
// rest (f(0, 0) = 0, no time, no damping linear in the rates there): ddot(q) = -K q with
// K_ij = -df_i/dq_j at 0 (a turning strand's length through its root), and the frequencies
// from K's eigenvalues with the numbers. Nothing when it does not rest there, or is unstable.
std::optional<EquationsOfMotion::Linearised> linearised_system(const Model& m, const EquationsOfMotion& eom) {
  const std::size_t n = eom.dof;
  exmap at_rest, roots;
  for (std::size_t i = 0; i < n; ++i) at_rest[eom.q[i]] = 0, at_rest[eom.dq[i]] = 0;
  for (const auto& l : m.lengths) roots[l.symbol] = sqrt(l.squared);
  EquationsOfMotion::Linearised lin;
  lin.about = 0;
  lin.stiffness_matrix = matrix(static_cast<unsigned>(n), static_cast<unsigned>(n));
  for (std::size_t i = 0; i < n; ++i) {
    const ex& f0 = eom.acceleration[i];
    if (f0.has(m.time)) return std::nullopt;
    const ex f = roots.empty() ? f0 : f0.subs(roots);
    auto at_zero = [&](const ex& e) -> std::optional<ex> {
      const ex nd = numer_denom(normal(e));
      const ex d0 = nd.op(1).subs(at_rest);
      if (zero(d0)) return std::nullopt;
      return normal(nd.op(0).subs(at_rest) / d0);
    };
    const auto rest = at_zero(f);
    if (!rest || !zero(*rest)) return std::nullopt;
    for (std::size_t j = 0; j < n; ++j) {
      if (f.has(eom.dq[j])) {
        const auto c = at_zero(f.diff(ex_to<symbol>(eom.dq[j])));
        if (!c || !zero(*c)) return std::nullopt;  // damped: not the undamped modes
      }
      if (!f.has(eom.q[j])) continue;
      const auto k = at_zero(-f.diff(ex_to<symbol>(eom.q[j])));
      if (!k) return std::nullopt;
      lin.stiffness_matrix(static_cast<unsigned>(i), static_cast<unsigned>(j)) = *k;
    }
  }
  const auto frequencies = small_oscillations(m, lin.stiffness_matrix);
  if (!frequencies) return std::nullopt;  // not a stable rest
  lin.frequencies = *frequencies;
  return lin;
}

// Small oscillations of one nonlinear degree of freedom about q0 = 0 where it is at rest
// (f(0, 0) = 0), when f depends on the coordinate alone: ddot(q) = -lambda^2 q with
// lambda^2 = -f'(0) (the pendulum's g/l). Nothing when it does not rest there, or is unstable.
std::optional<EquationsOfMotion::Linearised> linearised(const Model& m, const EquationsOfMotion& eom) {
  const ex& f = eom.acceleration[0];
  const ex& q = eom.q[0];
  if (f.has(eom.dq[0]) || f.has(m.time)) return std::nullopt;
  for (const auto& l : m.lengths)
    if (f.has(l.symbol)) return std::nullopt;
  EquationsOfMotion::Linearised lin;
  lin.about = 0;
  // f = n/d; a force such as -K/x^2 is undefined at 0 (d(0) = 0): no rest there. (Told
  // before anything is put in: GiNaC's division by zero leaks what it was building.)
  const ex nd = numer_denom(normal(f));
  const ex n0 = nd.op(0).subs(q == 0), d0 = nd.op(1).subs(q == 0);
  if (zero(d0) || !zero(n0)) return std::nullopt;
  // f'(0) = n'(0)/d(0), as n(0) = 0.
  lin.stiffness = normal(-nd.op(0).diff(ex_to<symbol>(q)).subs(q == 0) / d0);
  if (lin.stiffness.is_zero()) return std::nullopt;
  ex k_defined = lin.stiffness;
  for (int depth = 0; depth < 8; ++depth) k_defined = substituted(k_defined, m.symbols->definitions());
  if (const auto k = NormalForm(k_defined).approx_at(m.symbols->values())) {
    if (*k <= 0) return std::nullopt;  // not a stable rest: no oscillation about it
    lin.lambda = std::sqrt(*k);
  }
  return lin;
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
    if (auto v = NormalForm(*out.direction_until).approx_at(values)) out.direction_until_s = *v;
    else out.direction_unknown = true;
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
    if (start_sign == 0) start_sign = *v;  // from rest: the sign it takes
    else if ((*v > 0) != (start_sign > 0) || *v == 0) {
      double lo = horizon * (i - 1) / steps, hi = t1;
      for (int k = 0; k < 60; ++k) {
        const double mid = (lo + hi) / 2;
        const auto w = rate_at(mid);
        if (!w) break;
        ((*w > 0) == (start_sign > 0) && *w != 0 ? lo : hi) = mid;
      }
      out.direction_until_s = hi;
      return;
    }
  }
  out.direction_kept = true;
}

}  // namespace

std::optional<Motion> analyze_motion(const Model& m, const EquationSystem& s, const Solution& sol) {
  if (!m.motion) return std::nullopt;
  const MotionSpec& spec = *m.motion;
  const SymbolTable& table = *m.symbols;
  Motion out;
  EquationsOfMotion& eom = out.eom;
  eom.dof = spec.coordinates.size();
  eom.moving = spec.moving;
  eom.q = spec.coordinates;
  eom.dq = spec.rates;
  eom.ddq = spec.accelerations;
  if (sol.status == Solution::Status::inconsistent) {
    out.problem = "the equations are inconsistent, so there is no motion to follow";
    return out;
  }
  if (!sol.unsolved.empty()) {
    follow_mass_form(m, sol.mass_form, out);
    return out;
  }
  std::vector<ex> state = eom.q;
  state.insert(state.end(), eom.dq.begin(), eom.dq.end());
  // The accelerations of the motion's coordinates, from the solve.
  ex all = 0;
  for (const auto& a : eom.ddq) {
    auto v = sol.value_of(a);
    if (!v) {
      out.problem = "the equations do not determine " + to_text(a) + ", so the motion cannot be followed";
      return out;
    }
    eom.acceleration.push_back(*v);
    all += *v;
  }
  // The dependent coordinates are needed wherever the motion follows something: the
  // accelerations (without them there is no motion), then the quantities asked for and the
  // validity conditions (a string's T >= 0 in the spring end x_S = 2 x + C of a string over a
  // movable pulley); what cannot be followed is said, never dropped.
  const Dependents for_accelerations = dependents(m, s, sol, spec, all);
  if (!for_accelerations.problem.empty()) {
    out.problem = for_accelerations.problem;
    return out;
  }
  // A dependent rate that 'initial' gives must be the one the constraints give at t = 0.
  for (const auto& [sym, where] : spec.initial_at) {
    const auto r = for_accelerations.rates.find(sym);
    if (r == for_accelerations.rates.end()) continue;
    ex expected = r->second;
    for (int depth = 0; depth < 4; ++depth) expected = substituted(substituted(expected, spec.initial), for_accelerations.definitions);
    if (depends_on_state(expected, state, m)) continue;  // (not decidable here: followed as given)
    const ex given = spec.initial.at(sym);
    const ex difference = normal(given - expected);
    if (difference.is_zero()) continue;
    // Not the same expression: the same number at the parameters' values (to 1e-9) will do.
    const exmap values = table.values();
    const ex d = evalf(difference.subs(values)), e = evalf(expected.subs(values));
    if (is_a<numeric>(d) && is_a<numeric>(e) &&
        std::abs(ex_to<numeric>(d).to_double()) <= 1e-9 * std::max(1.0, std::abs(ex_to<numeric>(e).to_double())))
      continue;
    out.problem = "initial value of '" + to_text(sym) + "' is " + to_text(given) + ", but the constraints give " + to_text(sym) +
                  " = " + to_text(normal(r->second)) + " = " + to_text(normal(expected)) +
                  " at t = 0 (expected that value, or none: it follows from the motion's rates)";
    out.problem_at = where;
    return out;
  }
  const ex accelerations_only = all;
  for (const auto& w : m.wanted) all += substituted(w.expr, sol.general);
  for (const auto& c : sol.conditions)
    if (!c.depends_on_free) all += c.expr;
  // (Solved again only when the quantities and conditions add something to what is needed.)
  Dependents for_all = all.is_equal(accelerations_only) ? for_accelerations : dependents(m, s, sol, spec, all);
  const Dependents& dep = for_all.problem.empty() ? for_all : for_accelerations;
  // A coordinate (or rate) of a body that is neither the motion's nor given by it.
  auto unplaced = [&](const ex& e) -> std::optional<ex> {
    for (const auto& c : m.coordinates)
      if (!contains(state, c.q) && !dep.coords.count(c.q) && e.has(c.q)) return c.q;
    for (const auto& c : m.coordinates)
      if (!contains(state, c.rate) && !dep.rates.count(c.rate) && e.has(c.rate)) return c.rate;
    return std::nullopt;
  };
  for (auto& a : eom.acceleration) {
    a = normal(put_in(a, dep));
    for (const auto& c : m.candidates)
      if (a.has(c)) {
        out.problem = "the acceleration " + to_text(eom.ddq[&a - eom.acceleration.data()]) + " still contains " +
                      to_text(c) + ", which no equation gives";
        return out;
      }
    for (const auto& b : m.coordinates)
      if ((a.has(b.q) || a.has(b.rate)) && !contains(state, a.has(b.q) ? b.q : b.rate)) {
        out.problem = "the acceleration " + to_text(eom.ddq[&a - eom.acceleration.data()]) + " depends on " +
                      to_text(a.has(b.q) ? b.q : b.rate) + ", which the constraints do not give from the motion's coordinates";
        return out;
      }
  }

  // Linear with constant coefficients? ddot(q) = A q + B dot(q) + f(t).
  const ex& t = m.time;
  const std::size_t n = eom.dof;
  matrix A(n, n), B(n, n);
  std::vector<ex> f(n);
  eom.linear = true;
  for (std::size_t i = 0; i < n && eom.linear; ++i) {
    const ex& a = eom.acceleration[i];
    for (const auto& l : m.lengths)
      if (a.has(l.symbol)) {
        eom.linear = false;
        eom.nonlinear = "a strand's length " + to_text(l.symbol) + " turns with the coordinates";
      }
    if (!eom.linear) break;
    exmap zero_state;
    for (const auto& x : state) zero_state[x] = 0;
    ex rest = a;
    for (std::size_t j = 0; j < n && eom.linear; ++j)
      for (const bool rate : {false, true}) {
        const ex& x = rate ? eom.dq[j] : eom.q[j];
        const ex d = normal(a.diff(ex_to<symbol>(x)));
        if (depends_on_state(d, state, m) || d.has(t)) {
          eom.linear = false;
          eom.nonlinear = to_text(eom.ddq[i]) + " is not linear in " + to_text(x) + " with a constant coefficient";
          break;
        }
        (rate ? B : A)(i, j) = d;
        rest -= d * x;
      }
    if (!eom.linear) break;
    f[i] = normal(rest);
    if (depends_on_state(f[i], state, m)) {
      eom.linear = false;
      eom.nonlinear = to_text(eom.ddq[i]) + " is not linear in the coordinates and rates";
    }
  }
  // The mass matrix from the kinetic energy, with the dependent rates put in.
  bool mass_constant = true;
  {
    ex kinetic = 0;
    for (const auto& b : m.bodies)
      if (b.has_mass) kinetic += kinematics::kinetic_energy(m, b, [&](const ex& e) { return put_in(e, dep); });
    kinetic = kinetic.expand();
    eom.M = matrix(n, n);
    for (std::size_t i = 0; i < n; ++i)
      for (std::size_t j = 0; j < n; ++j) {
        eom.M(i, j) = normal(kinetic.diff(ex_to<symbol>(eom.dq[i])).diff(ex_to<symbol>(eom.dq[j])));
        if (depends_on_state(eom.M(i, j), state, m) || eom.M(i, j).has(t)) {
          mass_constant = false;
          if (eom.linear) eom.nonlinear = "the kinetic energy's coefficients change with the coordinates";
          eom.linear = false;
        }
      }
    if (mass_constant && zero(eom.M.determinant())) {
      mass_constant = false;
      if (eom.linear) eom.nonlinear = "the motion's coordinates carry no mass";
      eom.linear = false;
    }
  }
  // A mass matrix that turns with the coordinates (coupled links): the equations also as a
  // person writes them, M(q) q'' = F.
  if (!mass_constant && n > 1) take_mass_form(m, eom);
  if (eom.linear) {
    eom.K = matrix(n, n);
    eom.C = matrix(n, n);
    for (std::size_t i = 0; i < n; ++i) {
      ex Fi = 0;
      for (std::size_t j = 0; j < n; ++j) {
        ex kij = 0, cij = 0;
        for (std::size_t l = 0; l < n; ++l) {
          kij -= eom.M(i, l) * A(l, j);
          cij -= eom.M(i, l) * B(l, j);
        }
        eom.K(i, j) = simplest(kij);
        eom.C(i, j) = simplest(cij);
        Fi += eom.M(i, j) * f[j];
      }
      eom.forcing.push_back(simplest(Fi));
    }
    for (std::size_t i = 0; i < n; ++i)
      for (std::size_t j = 0; j < n; ++j) eom.M(i, j) = simplest(eom.M(i, j));
    bool constant = true;
    for (const auto& F : eom.forcing) constant = constant && !F.has(t);
    if (constant && !zero(eom.K.determinant())) {
      matrix rhs(n, 1);
      for (std::size_t i = 0; i < n; ++i) rhs(i, 0) = eom.forcing[i];
      const matrix qe = eom.K.inverse().mul(rhs);
      std::vector<ex> e;
      for (std::size_t i = 0; i < n; ++i) e.push_back(simplest(qe(i, 0)));
      eom.equilibrium = e;
    }
  }

  // More than one degree of freedom: the modes are numeric (Eigen), with the given values.
  if (eom.linear && n > 1) {
    const exmap values = table.values();
    Eigen::MatrixXd Mn(n, n), Kn(n, n);
    bool numbers = true;
    for (std::size_t i = 0; i < n && numbers; ++i)
      for (std::size_t j = 0; j < n && numbers; ++j) {
        const auto mv = NormalForm(eom.M(i, j)).approx_at(values), kv = NormalForm(eom.K(i, j)).approx_at(values);
        if (!mv || !kv) numbers = false;
        else Mn(i, j) = *mv, Kn(i, j) = *kv;
      }
    if (numbers && std::abs(Mn.determinant()) > 0) {
      const Eigen::EigenSolver<Eigen::MatrixXd> es(Mn.inverse() * Kn);
      bool real = es.info() == Eigen::Success;
      for (Eigen::Index i = 0; i < es.eigenvalues().size() && real; ++i) {
        const auto ev = es.eigenvalues()(i);
        if (std::abs(ev.imag()) > 1e-9 * (1 + std::abs(ev.real())) || ev.real() < 0) real = false;
        else eom.natural_frequencies.push_back(std::sqrt(std::max(0.0, ev.real())));
      }
      if (!real) eom.natural_frequencies.clear();
      std::sort(eom.natural_frequencies.begin(), eom.natural_frequencies.end());
    }
  }

  // One degree of freedom, linear: the response in closed form.
  if (n == 1 && eom.linear) {
    const ex M = eom.M(0, 0), C = eom.C(0, 0), K = eom.K(0, 0);
    const auto forcing = harmonic(eom.forcing[0], t);
    const exmap values = table.values();
    auto numeric_sign = [&](const ex& e) -> std::optional<int> {
      if (auto sg = sign_of(normal(e))) return sg;
      if (auto v = NormalForm(e).approx_at(values)) return *v > 0 ? 1 : (*v < 0 ? -1 : 0);
      return std::nullopt;
    };
    if (!forcing) {
      out.no_response = "the forcing " + to_text(eom.forcing[0]) + " is not a constant plus one harmonic term (simulate it)";
    } else if (!zero(K) && numeric_sign(K / M) != std::optional<int>(1)) {
      out.no_response = "the stiffness " + to_text(K) + " is not known to be positive";
    } else {
      Response r;
      const ex& lambda = spec.lambda;
      const ex& zeta = spec.zeta;
      const ex& wd = spec.omega_d;
      ex h1, h2;
      const bool undamped = zero(C), unsprung = zero(K);
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
        const auto sg = zero(disc) ? std::optional<int>(0) : numeric_sign(disc);
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
      // The forced part.
      ex qp = 0;
      const ex F0 = forcing->constant;
      if (!zero(F0)) qp += simplest(!unsprung ? F0 / K : (!undamped ? F0 * t / C : F0 * pow(t, 2) / (2 * M)));
      bool resonant = false;
      if (!zero(forcing->a) || !zero(forcing->b)) {
        const ex w = forcing->w;
        const ex k = K - M * pow(w, 2), c = C * w;
        const ex det = normal(k * k + c * c);
        if (det.is_zero()) {
          resonant = true;
          out.no_response = "the forcing is at the natural frequency (resonance; simulate it)";
        } else {
          const ex X = simplest((k * forcing->a - c * forcing->b) / det);
          const ex Y = simplest((c * forcing->a + k * forcing->b) / det);
          qp += X * cos(w * t) + Y * sin(w * t);
          if (undamped) r.assumptions.push_back({w, lambda, "!=", "no resonance"});
          r.forcing_frequency = w;
        }
      }
      if (!resonant) {
        // The constants from q(0) = q0, dot(q)(0) = v0.
        const symbol a("a"), b("b");
        const ex trial = qp + a * h1 + b * h2;
        const ex q0 = spec.initial.at(eom.q[0]), v0 = spec.initial.at(eom.dq[0]);
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
        for (const auto& [sym, def] : r.definitions) out.definitions[sym] = def;
        // Verified: M q'' + C q' + K q - F(t) at random parameter values and times. The
        // defined parameters (every geometric length too) and the response's own definitions
        // are put in first, so that the residual and its scale are in the free parameters and
        // t only; both are compiled once and evaluated in doubles.
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
            if (it == p.end()) valued = false;
            else x[i] = ex_to<numeric>(it->second).to_double();
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
        ok = ok && checked > 0;
        r.verified = ok;
        out.response = std::move(r);
        if (!m.direction_assumed_by.empty()) sliding_interval(out, m, spec);
      }
    }
  } else if (!eom.linear) {
    out.no_response = "the equation of motion is nonlinear (" + eom.nonlinear + "; simulate it)";
    eom.linearised = n == 1 ? linearised(m, eom) : linearised_system(m, eom);
  } else {
    out.no_response = std::to_string(n) + " degrees of freedom (the modes are numeric; simulate the motion)";
  }
  // The speed at a position, from the work-energy balance.
  if (spec.speed_at) out.energy = work_energy(m, eom, spec, mass_constant);

  // Everything a simulation reports, in the state.
  for (const auto& [sym, value] : dep.coords) out.in_state.emplace_back(sym, value);
  for (const auto& [sym, value] : dep.rates) out.in_state.emplace_back(sym, put_in(value, dep));
  for (const auto& w : m.wanted) {
    const SymbolInfo* si = table.find(w.name);
    if (!si) continue;
    const ex value = put_in(substituted(w.expr, sol.general), dep);
    bool known = !unplaced(value);
    for (const auto& c : m.candidates)
      if (value.has(c)) known = false;
    if (known) out.in_state.emplace_back(si->sym, value);
  }
  // Every other unknown the solve determines (a tension to plot that `find` does not list).
  for (const auto& u : s.unknowns) {
    if (std::any_of(out.in_state.begin(), out.in_state.end(), [&](const auto& p) { return p.first.is_equal(u); })) continue;
    const ex value = put_in(substituted(u, sol.general), dep);
    if (std::none_of(m.candidates.begin(), m.candidates.end(), [&](const ex& c) { return value.has(c); }))
      out.in_state.emplace_back(u, value);
  }
  // A condition through a coordinate the motion cannot place (its starting value not given)
  // is not followed in time: said, with the reason.
  for (const auto& c : sol.conditions) {
    if (c.depends_on_free) continue;
    const ex in_state = put_in(c.expr, dep);
    if (const auto q = unplaced(in_state)) {
      out.not_followed.emplace_back(c.condition->source,
                                    "it depends on " + to_text(*q) +
                                        (for_all.problem.empty() ? ", which the motion's coordinates do not give"
                                                                 : ", whose value at t = 0 'initial' does not give (expected it there)"));
      continue;
    }
    out.conditions_in_state.emplace_back(&c, in_state);
  }
  // The strands' lengths need the dependent coordinates too (a block running into the pulley
  // over it): placed from 'initial' where it gives their starts, each strand on its own terms.
  // (Solved again only when a strand needs a coordinate the quantities and conditions do not.)
  ex with_strands = all;
  bool unplaced_strand = false;
  for (const auto& [length, what] : m.strand_lengths) {
    with_strands += length;
    unplaced_strand = unplaced_strand || unplaced(put_in(length, dep)).has_value();
  }
  const Dependents for_strands =
      !unplaced_strand || !for_all.problem.empty() ? for_all : dependents(m, s, sol, spec, with_strands);
  const Dependents& strand_dep = for_strands.problem.empty() ? for_strands : dep;
  auto strand_unplaced = [&](const ex& e) -> std::optional<ex> {
    for (const auto& c : m.coordinates)
      if (!contains(state, c.q) && !strand_dep.coords.count(c.q) && e.has(c.q)) return c.q;
    return std::nullopt;
  };
  for (const auto& [length, what] : m.strand_lengths) {
    // A strand through a coordinate whose starting value is not given cannot be followed to
    // the moment it closes (a block running into its pulley): said, as for a condition.
    const ex in_state = put_in(length, strand_dep);
    // (A strand whose length stays what it was at t = 0, as between bodies in contact, is no
    // concern even where that length is not known.)
    if (const auto q = strand_unplaced(in_state)) {
      if (!zero(put_in(time_derivative(length, m), strand_dep)))
        out.not_followed.emplace_back(what, "its length depends on " + to_text(*q) +
                                                ", whose value at t = 0 'initial' does not give (expected it there)");
      continue;
    }
    if (depends_on_state(in_state, state, m) || in_state.has(m.time)) out.strands_in_state.emplace_back(what, in_state);
  }
  for (const auto& slip : m.slips) out.slips_in_state.emplace_back(slip.source, put_in(slip.speed, dep));
  if (!m.direction_assumed_by.empty()) out.direction_against = against_at_start(m, sol, dep, spec);
  if (!out.response) return out;

  // The quantities asked for, along the response.
  const Response& r = *out.response;
  exmap along{{eom.q[0], r.q}, {eom.dq[0], r.rate}};
  // The lambda form: the stiffness's one symbol replaced by lambda^2 times the mass (k ->
  // lambda^2 (m + M)), where that is shorter.
  // Remembered: a condition is often a quantity asked for (N >= 0 with N found). The normal
  // forms are remembered too, so that simplest() does not make them again.
  std::vector<std::pair<ex, ex>> lambda_forms;
  auto in_lambda = [&](const ex& e) {
    for (const auto& [key, form] : lambda_forms)
      if (key.is_equal(e)) return form;
    const ex plain = normal_remembered(e);
    const ex K = eom.K(0, 0), M = eom.M(0, 0);
    ex chosen = plain;
    if (r.regime == Response::Regime::undamped && is_a<symbol>(K)) {
      const ex alt = normal_remembered(e.subs(K == pow(spec.lambda, 2) * M));
      if (to_text(alt).size() < to_text(plain).size()) chosen = alt;
    }
    const ex form = simplest(chosen);
    lambda_forms.emplace_back(e, form);
    return form;
  };
  for (const auto& w : m.wanted) {
    ex value = w.defined ? substituted(w.expr, sol.general) : substituted(w.expr, sol.general);
    value = put_in(value, dep);
    bool known = !unplaced(value);
    for (const auto& c : m.candidates)
      if (value.has(c)) known = false;
    if (!known) continue;
    if (!value.has(eom.q[0]) && !value.has(eom.dq[0]) && !value.has(t)) continue;  // constant in time
    QuantityInTime qt;
    qt.name = w.name;
    qt.tex = w.tex;
    if (const SymbolInfo* si = table.find(w.name)) qt.symbol = si->sym;
    qt.of_t = in_lambda(substituted(value, along));
    qt.dimension = w.dimension;
    out.quantities.push_back(std::move(qt));
  }
  // Each validity condition along the response.
  const auto params = parameters_of(table);
  const exmap values = table.values();
  for (const auto& c : sol.conditions) {
    if (c.depends_on_free) continue;
    const ex in_state = put_in(c.expr, dep);
    if (!out.not_followed.empty() && std::any_of(out.not_followed.begin(), out.not_followed.end(),
                                                 [&](const auto& nf) { return nf.first == c.condition->source; }))
      continue;
    if (!in_state.has(eom.q[0]) && !in_state.has(eom.dq[0]) && !in_state.has(t)) continue;  // constant in time
    ConditionInTime ct;
    ct.condition = *c.condition;
    const ex g = substituted(in_state, along);
    ct.of_t = in_lambda(g);
    const std::string& op = c.condition->op;
    if (r.regime == Response::Regime::undamped) {
      // g = alpha + beta cos(lambda t) + gamma sin(lambda t)
      const symbol cs("cs"), sn("sn");
      const ex lt = spec.lambda * t;
      const ex p = normal(g).subs(lst{cos(lt) == cs, sin(lt) == sn}).expand();
      if (!p.has(t) && p.degree(cs) <= 1 && p.degree(sn) <= 1 && !p.coeff(cs, 1).has(sn)) {
        const ex alpha = simplest(p.subs(lst{cs == 0, sn == 0}));
        const ex beta = simplest(p.coeff(cs, 1)), gamma = simplest(p.coeff(sn, 1));
        ex amplitude;
        std::optional<int> beta_sign = sign_of(beta);
        if (gamma.is_zero() && beta_sign) amplitude = *beta_sign >= 0 ? beta : -beta;
        else amplitude = sqrt(simplest(beta * beta + gamma * gamma));
        const bool lower = op == ">=" || op == ">";
        const ex extreme = lower ? alpha - amplitude : alpha + amplitude;
        ct.extreme = in_lambda(extreme);
        if (gamma.is_zero() && beta_sign && *beta_sign != 0)
          ct.extreme_at = (lower == (*beta_sign > 0)) ? Pi / spec.lambda : ex(0);
        if (is_rational_function(extreme)) ct.solved = solve_condition(simplest(extreme), op, params);
        exmap all_values = values;
        for (const auto& [sym, def] : out.definitions) all_values[sym] = substituted(def, values);
        if (auto v = NormalForm(extreme).approx_at(all_values)) {
          ct.holds_for_all_t = lower ? (op == ">=" ? *v >= 0 : *v > 0) : (op == "<=" ? *v <= 0 : *v < 0);
        }
        // The first failure: alpha + beta cos(lambda t) crosses 0 at acos(-alpha/beta)/lambda.
        if (gamma.is_zero() && beta_sign && ((lower && *beta_sign > 0) || (!lower && *beta_sign < 0))) {
          ct.first_failure = acos(in_lambda(-alpha / beta)) / spec.lambda;
          if (ct.holds_for_all_t == false) {
            const ex v = evalf(substituted(substituted(*ct.first_failure, all_values), all_values));
            if (is_a<numeric>(v) && ex_to<numeric>(v).is_real()) ct.first_failure_s = ex_to<numeric>(v).to_double();
          }
        }
      }
    }
    if (!r.forcing_frequency.is_zero()) steady_state(ct, c, in_state, r, eom, m, values);
    out.conditions.push_back(std::move(ct));
  }
  return out;
}

}  // namespace tackle
