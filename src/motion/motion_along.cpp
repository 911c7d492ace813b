// Along the closed-form response: each quantity asked for and each validity condition as a
// function of time, a condition's extreme over all t (undamped) and its steady state (under
// a harmonic forcing).
#include "motion/motion_detail.hpp"

#include <algorithm>
#include <tuple>

#include "expr/normal_form.hpp"
#include "expr/print.hpp"
#include "expr/rational.hpp"

namespace tackle::motion_detail {

using namespace GiNaC;

namespace {

// The parameters of the problem, for solving conditions.
std::vector<ex> parameters_of(const SymbolTable& t) {
  std::vector<ex> out;
  for (const auto& s : t.all())
    if (s->role == SymbolRole::parameter && !s->geometric) out.push_back(s->sym);
  return out;
}

// `g` as alpha + beta cos(w t) + gamma sin(w t), each part free of t (nothing when it is not
// one). Where `g` is affine in the cosine and the sine as written (its derivatives in them
// free of both), each part is put over one denominator alone: normal() of the whole, with
// the particular solution's coefficients over theirs, was most of a driven slope's run.
std::tuple<std::optional<ex>, std::optional<ex>, std::optional<ex>> harmonic_parts(const ex& g, const ex& cos_wt,
                                                                                   const ex& sin_wt, const ex& t) {
  const symbol cs("cs"), sn("sn");
  const ex in_cs = g.subs(lst{cos_wt == cs, sin_wt == sn});
  const ex d_cs = in_cs.diff(cs), d_sn = in_cs.diff(sn);
  if (!d_cs.has(cs) && !d_cs.has(sn) && !d_sn.has(cs) && !d_sn.has(sn)) {
    const ex alpha = normal(in_cs.subs(lst{cs == 0, sn == 0})), beta = normal(d_cs), gamma = normal(d_sn);
    if (alpha.has(t) || beta.has(t) || gamma.has(t)) return {};
    return {alpha, beta, gamma};
  }
  const ex p = normal(g).subs(lst{cos_wt == cs, sin_wt == sn}).expand();
  if (p.has(t) || !p.is_polynomial(lst{cs, sn}) || p.degree(cs) > 1 || p.degree(sn) > 1 || p.coeff(cs, 1).has(sn))
    return {};
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
  const ex g = substituted(substituted(in_state, m.symbols->definitions()),
                           exmap{{eom.q[0], qp}, {eom.dq[0], qp.diff(ex_to<symbol>(t))}});
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
  ct.steady_amplitude_condition = gamma.is_zero()
                                      ? simplest_of_product(num, {numer_denom_remembered(alpha - beta).op(0),
                                                                  numer_denom_remembered(alpha + beta).op(0)})
                                      : simplest(num);
  if (const auto v =
          NormalForm(lower ? alpha - sqrt(beta * beta + gamma * gamma) : alpha + sqrt(beta * beta + gamma * gamma))
              .approx_at(values))
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

// The lambda form: the stiffness's one symbol replaced by lambda^2 times the mass (k ->
// lambda^2 (m + M)), where that is shorter.
// Remembered: a condition is often a quantity asked for (N >= 0 with N found). The normal
// forms are remembered too, so that simplest() does not make them again.
struct InLambda {
  const Response& r;
  const EquationsOfMotion& eom;
  const MotionSpec& spec;
  std::vector<std::pair<ex, ex>> lambda_forms;

  // `e` in its lambda form, simplest.
  ex operator()(const ex& e) {
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
  }
};

// What the steps along the response share: the motion, the response, the motion's
// coordinate and rate along it, and the lambda forms made.
struct Along {
  MotionStory& st;
  const Response& r;
  exmap along;
  InLambda in_lambda;
};

// The quantities asked for, along the response (those constant in time are not).
void quantities_along(Along& a) {
  const Model& m = a.st.m;
  const Dependents& dep = *a.st.dep;
  const EquationsOfMotion& eom = a.st.eom;
  const ex& t = m.time;
  for (const auto& w : m.wanted) {
    ex value = w.defined ? substituted(w.expr, a.st.sol.general) : substituted(w.expr, a.st.sol.general);
    value = put_in(value, dep);
    bool known = !a.st.unplaced(value);
    for (const auto& c : m.candidates)
      if (value.has(c)) known = false;
    if (!known) continue;
    if (!value.has(eom.q[0]) && !value.has(eom.dq[0]) && !value.has(t)) continue;  // constant in time
    QuantityInTime qt;
    qt.name = w.name;
    qt.tex = w.tex;
    if (const SymbolInfo* si = a.st.table.find(w.name)) qt.symbol = si->sym;
    qt.of_t = a.in_lambda(substituted(value, a.along));
    qt.dimension = w.dimension;
    a.st.out.quantities.push_back(std::move(qt));
  }
}

// An undamped response's condition, g = alpha + beta cos(lambda t) + gamma sin(lambda t):
// its extreme over all t and where it is first reached, the condition for all t solved for
// the parameters, whether it holds with the numbers, and where it first fails.
void undamped_extreme(ConditionInTime& ct, const ex& g, const std::string& op, Along& a, const std::vector<ex>& params,
                      const exmap& values) {
  const MotionSpec& spec = a.st.spec;
  const ex& t = a.st.m.time;
  InLambda& in_lambda = a.in_lambda;
  // g = alpha + beta cos(lambda t) + gamma sin(lambda t)
  const symbol cs("cs"), sn("sn");
  const ex lt = spec.lambda * t;
  const ex p = normal(g).subs(lst{cos(lt) == cs, sin(lt) == sn}).expand();
  if (!p.has(t) && p.degree(cs) <= 1 && p.degree(sn) <= 1 && !p.coeff(cs, 1).has(sn)) {
    const ex alpha = simplest(p.subs(lst{cs == 0, sn == 0}));
    const ex beta = simplest(p.coeff(cs, 1)), gamma = simplest(p.coeff(sn, 1));
    ex amplitude;
    std::optional<int> beta_sign = sign_of(beta);
    if (gamma.is_zero() && beta_sign)
      amplitude = *beta_sign >= 0 ? beta : -beta;
    else
      amplitude = sqrt(simplest(beta * beta + gamma * gamma));
    const bool lower = op == ">=" || op == ">";
    const ex extreme = lower ? alpha - amplitude : alpha + amplitude;
    ct.extreme = in_lambda(extreme);
    if (gamma.is_zero() && beta_sign && *beta_sign != 0)
      ct.extreme_at = (lower == (*beta_sign > 0)) ? Pi / spec.lambda : ex(0);
    if (is_rational_function(extreme)) ct.solved = solve_condition(simplest(extreme), op, params);
    exmap all_values = values;
    for (const auto& [sym, def] : a.st.out.definitions) all_values[sym] = substituted(def, values);
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

// Each validity condition along the response (those constant in time, or not followed, are
// not): its expression in time, its extreme (undamped) and its steady state (forced).
void conditions_along(Along& a) {
  const Model& m = a.st.m;
  const Dependents& dep = *a.st.dep;
  const EquationsOfMotion& eom = a.st.eom;
  const Response& r = a.r;
  Motion& out = a.st.out;
  const ex& t = m.time;
  const auto params = parameters_of(a.st.table);
  const exmap values = a.st.table.values();
  for (const auto& c : a.st.sol.conditions) {
    if (c.depends_on_free) continue;
    const ex in_state = put_in(c.expr, dep);
    if (!out.not_followed.empty() && std::any_of(out.not_followed.begin(), out.not_followed.end(),
                                                 [&](const auto& nf) { return nf.first == c.condition->source; }))
      continue;
    if (!in_state.has(eom.q[0]) && !in_state.has(eom.dq[0]) && !in_state.has(t)) continue;  // constant in time
    ConditionInTime ct;
    ct.condition = *c.condition;
    const ex g = substituted(in_state, a.along);
    ct.of_t = a.in_lambda(g);
    const std::string& op = c.condition->op;
    if (r.regime == Response::Regime::undamped) undamped_extreme(ct, g, op, a, params, values);
    if (!r.forcing_frequency.is_zero()) steady_state(ct, c, in_state, r, eom, m, values);
    out.conditions.push_back(std::move(ct));
  }
}

}  // namespace

void along_response(MotionStory& st) {
  // The quantities asked for, along the response.
  const Response& r = *st.out.response;
  Along a{st, r, exmap{{st.eom.q[0], r.q}, {st.eom.dq[0], r.rate}}, InLambda{r, st.eom, st.spec, {}}};
  quantities_along(a);
  // Each validity condition along the response.
  conditions_along(a);
}

}  // namespace tackle::motion_detail
