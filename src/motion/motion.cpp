#include "motion/motion.hpp"

#include "motion/mass_form.hpp"
#include "motion/motion_detail.hpp"

#include <algorithm>
#include <cmath>

#include <Eigen/Dense>

#include "expr/normal_form.hpp"
#include "expr/print.hpp"
#include "expr/rational.hpp"
#include "model/kinematics.hpp"
#include "numeric/compiled.hpp"

namespace tackle {

using namespace GiNaC;
using namespace motion_detail;

namespace motion_detail {

std::optional<ex> MotionStory::unplaced(const ex& e) const {
  for (const auto& c : m.coordinates)
    if (!contains(state, c.q) && !dep->coords.count(c.q) && e.has(c.q)) return c.q;
  for (const auto& c : m.coordinates)
    if (!contains(state, c.rate) && !dep->rates.count(c.rate) && e.has(c.rate)) return c.rate;
  return std::nullopt;
}

}  // namespace motion_detail

namespace {

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
  const bool geometric =
      std::any_of(m.lengths.begin(), m.lengths.end(), [&](const TurningLength& l) { return Q.has(l.symbol); });
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
  const auto a = NormalForm(q0).approx_at(values), b = NormalForm(q1).approx_at(values),
             mv = NormalForm(M).approx_at(values), v0n = NormalForm(v0).approx_at(values);
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
  static const double w5[] = {0.5688888888888889, 0.4786286704993665, 0.4786286704993665, 0.2369268850561891,
                              0.2369268850561891};
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
    if (v && *v < -1e-9)
      return "at t = 0 the contact of " + s.source +
             " slips against the direction it assumes (its friction would push the bodies along, not hold them back)";
  }
  for (const auto& l : m.loads) {
    if (l.body < 0 || std::find(m.direction_assumed_by.begin(), m.direction_assumed_by.end(), l.source()) ==
                          m.direction_assumed_by.end())
      continue;
    // (Between two bodies, the relative slip above decides, not each body's own motion.)
    if (std::any_of(m.slips.begin(), m.slips.end(),
                    [&](const Model::Slip& s) { return s.source == l.source() && s.bodies.size() > 1; }))
      continue;
    const Body& b = m.bodies[static_cast<std::size_t>(l.body)];
    // The velocity of the point the friction acts at: the center's, unless the body turns.
    const bool turning = !b.angle.is_zero() && l.at;
    const auto velocity = turning ? kinematics::point_velocity(m, b, *l.at - b.cm) : kinematics::velocity(m, b);
    if (!velocity) continue;
    Vec acceleration = kinematics::acceleration(m, b);
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
      return "at t = 0 body '" + b.name + "' moves against the sliding direction that " + l.source() +
             " assumes (its friction would push it along, not hold it back)";
    if (vv <= tiny * tiny && aa > tiny * tiny && fa > tiny * std::sqrt(ff * aa))
      return "from rest, the forces start body '" + b.name + "' against the sliding direction that " + l.source() +
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

// The accelerations of the motion's coordinates, from the solve (and the state they are in:
// the coordinates, then the rates); false, with the problem said, when one is not determined.
bool take_accelerations(MotionStory& st) {
  EquationsOfMotion& eom = st.eom;
  st.state = eom.q;
  st.state.insert(st.state.end(), eom.dq.begin(), eom.dq.end());
  for (const auto& a : eom.ddq) {
    auto v = st.sol.value_of(a);
    if (!v) {
      st.out.problem = "the equations do not determine " + to_text(a) + ", so the motion cannot be followed";
      return false;
    }
    eom.acceleration.push_back(*v);
    st.all += *v;
  }
  return true;
}

// A dependent rate that 'initial' gives must be the one the constraints give at t = 0: false,
// with the problem said where 'initial' gives it, when it is not.
bool initial_rates_agree(MotionStory& st) {
  const Model& m = st.m;
  const MotionSpec& spec = st.spec;
  const Dependents& for_accelerations = st.for_accelerations;
  for (const auto& [sym, where] : spec.initial_at) {
    const auto r = for_accelerations.rates.find(sym);
    if (r == for_accelerations.rates.end()) continue;
    ex expected = r->second;
    for (int depth = 0; depth < 4; ++depth)
      expected = substituted(substituted(expected, spec.initial), for_accelerations.definitions);
    if (depends_on_state(expected, st.state, m)) continue;  // (not decidable here: followed as given)
    const ex given = spec.initial.at(sym);
    const ex difference = normal(given - expected);
    if (difference.is_zero()) continue;
    // Not the same expression: the same number at the parameters' values (to 1e-9) will do.
    const exmap values = st.table.values();
    const ex d = evalf(difference.subs(values)), e = evalf(expected.subs(values));
    if (is_a<numeric>(d) && is_a<numeric>(e) &&
        std::abs(ex_to<numeric>(d).to_double()) <= 1e-9 * std::max(1.0, std::abs(ex_to<numeric>(e).to_double())))
      continue;
    st.out.problem = "initial value of '" + to_text(sym) + "' is " + to_text(given) + ", but the constraints give " +
                     to_text(sym) + " = " + to_text(normal(r->second)) + " = " + to_text(normal(expected)) +
                     " at t = 0 (expected that value, or none: it follows from the motion's rates)";
    st.out.problem_at = where;
    return false;
  }
  return true;
}

// The dependents for everything the motion follows: the accelerations, then the quantities
// asked for and the validity conditions; the ones the steps put in (those of the
// accelerations alone where the others cannot be placed).
void place_dependents(MotionStory& st) {
  const ex accelerations_only = st.all;
  for (const auto& w : st.m.wanted) st.all += substituted(w.expr, st.sol.general);
  for (const auto& c : st.sol.conditions)
    if (!c.depends_on_free) st.all += c.expr;
  // (Solved again only when the quantities and conditions add something to what is needed.)
  st.for_all =
      st.all.is_equal(accelerations_only) ? st.for_accelerations : dependents(st.m, st.s, st.sol, st.spec, st.all);
  st.dep = st.for_all.problem.empty() ? &st.for_all : &st.for_accelerations;
}

// The accelerations with the dependents put in: false, with the problem said, when one still
// has an unknown that no equation gives, or a coordinate the constraints do not give.
bool accelerations_in_state(MotionStory& st) {
  const Model& m = st.m;
  EquationsOfMotion& eom = st.eom;
  for (auto& a : eom.acceleration) {
    a = normal(put_in(a, *st.dep));
    for (const auto& c : m.candidates)
      if (a.has(c)) {
        st.out.problem = "the acceleration " + to_text(eom.ddq[&a - eom.acceleration.data()]) + " still contains " +
                         to_text(c) + ", which no equation gives";
        return false;
      }
    for (const auto& b : m.coordinates)
      if ((a.has(b.q) || a.has(b.rate)) && !contains(st.state, a.has(b.q) ? b.q : b.rate)) {
        st.out.problem = "the acceleration " + to_text(eom.ddq[&a - eom.acceleration.data()]) + " depends on " +
                         to_text(a.has(b.q) ? b.q : b.rate) +
                         ", which the constraints do not give from the motion's coordinates";
        return false;
      }
  }
  return true;
}

// ddot(q) = A q + B dot(q) + f(t), with A and B constant.
struct LinearForm {
  matrix A, B;
  std::vector<ex> f;
};

// Linear with constant coefficients? ddot(q) = A q + B dot(q) + f(t): A, B and f where it is
// (eom.linear); else eom.nonlinear says why.
LinearForm linear_form(MotionStory& st) {
  const Model& m = st.m;
  const std::vector<ex>& state = st.state;
  EquationsOfMotion& eom = st.eom;
  const ex& t = m.time;
  const std::size_t n = eom.dof;
  LinearForm lf{matrix(n, n), matrix(n, n), std::vector<ex>(n)};
  matrix &A = lf.A, &B = lf.B;
  std::vector<ex>& f = lf.f;
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
  return lf;
}

// The mass matrix from the kinetic energy, with the dependent rates put in; one that changes
// with the coordinates or time, or is singular, is no constant mass (and the motion is not
// linear).
void mass_matrix(MotionStory& st) {
  const Model& m = st.m;
  EquationsOfMotion& eom = st.eom;
  const ex& t = m.time;
  const std::size_t n = eom.dof;
  ex kinetic = 0;
  for (const auto& b : m.bodies)
    if (b.has_mass) kinetic += kinematics::kinetic_energy(m, b, [&](const ex& e) { return put_in(e, *st.dep); });
  kinetic = kinetic.expand();
  eom.M = matrix(n, n);
  for (std::size_t i = 0; i < n; ++i)
    for (std::size_t j = 0; j < n; ++j) {
      eom.M(i, j) = normal(kinetic.diff(ex_to<symbol>(eom.dq[i])).diff(ex_to<symbol>(eom.dq[j])));
      if (depends_on_state(eom.M(i, j), st.state, m) || eom.M(i, j).has(t)) {
        st.mass_constant = false;
        if (eom.linear) eom.nonlinear = "the kinetic energy's coefficients change with the coordinates";
        eom.linear = false;
      }
    }
  if (st.mass_constant && zero(eom.M.determinant())) {
    st.mass_constant = false;
    if (eom.linear) eom.nonlinear = "the motion's coordinates carry no mass";
    eom.linear = false;
  }
}

// Linear: M q'' + C q' + K q = F(t) with K = -M A, C = -M B and F = M f; and the equilibrium,
// K q = F, when F is constant and K invertible.
void stiffness_and_damping(MotionStory& st, const LinearForm& lf) {
  EquationsOfMotion& eom = st.eom;
  const ex& t = st.m.time;
  const std::size_t n = eom.dof;
  const matrix &A = lf.A, &B = lf.B;
  const std::vector<ex>& f = lf.f;
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

// More than one degree of freedom: the modes are numeric (Eigen), with the given values: the
// undamped natural frequencies, square roots of the eigenvalues of M^-1 K.
void natural_frequencies(MotionStory& st) {
  EquationsOfMotion& eom = st.eom;
  const std::size_t n = eom.dof;
  const exmap values = st.table.values();
  Eigen::MatrixXd Mn(n, n), Kn(n, n);
  bool numbers = true;
  for (std::size_t i = 0; i < n && numbers; ++i)
    for (std::size_t j = 0; j < n && numbers; ++j) {
      const auto mv = NormalForm(eom.M(i, j)).approx_at(values), kv = NormalForm(eom.K(i, j)).approx_at(values);
      if (!mv || !kv)
        numbers = false;
      else
        Mn(i, j) = *mv, Kn(i, j) = *kv;
    }
  if (numbers && std::abs(Mn.determinant()) > 0) {
    const Eigen::EigenSolver<Eigen::MatrixXd> es(Mn.inverse() * Kn);
    bool real = es.info() == Eigen::Success;
    for (Eigen::Index i = 0; i < es.eigenvalues().size() && real; ++i) {
      const auto ev = es.eigenvalues()(i);
      if (std::abs(ev.imag()) > 1e-9 * (1 + std::abs(ev.real())) || ev.real() < 0)
        real = false;
      else
        eom.natural_frequencies.push_back(std::sqrt(std::max(0.0, ev.real())));
    }
    if (!real) eom.natural_frequencies.clear();
    std::sort(eom.natural_frequencies.begin(), eom.natural_frequencies.end());
  }
}

// Everything a simulation reports, in the state: the dependent coordinates and rates, the
// quantities asked for, and every other unknown the solve determines.
void quantities_in_state(MotionStory& st) {
  const Model& m = st.m;
  const Dependents& dep = *st.dep;
  Motion& out = st.out;
  for (const auto& [sym, value] : dep.coords) out.in_state.emplace_back(sym, value);
  for (const auto& [sym, value] : dep.rates) out.in_state.emplace_back(sym, put_in(value, dep));
  for (const auto& w : m.wanted) {
    const SymbolInfo* si = st.table.find(w.name);
    if (!si) continue;
    const ex value = put_in(substituted(w.expr, st.sol.general), dep);
    bool known = !st.unplaced(value);
    for (const auto& c : m.candidates)
      if (value.has(c)) known = false;
    if (known) out.in_state.emplace_back(si->sym, value);
  }
  // Every other unknown the solve determines (a tension to plot that `find` does not list).
  for (const auto& u : st.s.unknowns) {
    if (std::any_of(out.in_state.begin(), out.in_state.end(), [&](const auto& p) { return p.first.is_equal(u); }))
      continue;
    const ex value = put_in(substituted(u, st.sol.general), dep);
    if (std::none_of(m.candidates.begin(), m.candidates.end(), [&](const ex& c) { return value.has(c); }))
      out.in_state.emplace_back(u, value);
  }
}

// Each validity condition in the state. One through a coordinate the motion cannot place
// (its starting value not given) is not followed in time: said, with the reason.
void conditions_in_state(MotionStory& st) {
  for (const auto& c : st.sol.conditions) {
    if (c.depends_on_free) continue;
    const ex in_state = put_in(c.expr, *st.dep);
    if (const auto q = st.unplaced(in_state)) {
      st.out.not_followed.emplace_back(
          c.condition->source,
          "it depends on " + to_text(*q) +
              (st.for_all.problem.empty() ? ", which the motion's coordinates do not give"
                                          : ", whose value at t = 0 'initial' does not give (expected it there)"));
      continue;
    }
    st.out.conditions_in_state.emplace_back(&c, in_state);
  }
}

// The strands' lengths in the state, which need the dependent coordinates too (a block
// running into the pulley over it): placed from 'initial' where it gives their starts, each
// strand on its own terms.
void strands_in_state(MotionStory& st) {
  const Model& m = st.m;
  const Dependents& dep = *st.dep;
  const std::vector<ex>& state = st.state;
  Motion& out = st.out;
  // (Solved again only when a strand needs a coordinate the quantities and conditions do not.)
  ex with_strands = st.all;
  bool unplaced_strand = false;
  for (const auto& [length, what] : m.strand_lengths) {
    with_strands += length;
    unplaced_strand = unplaced_strand || st.unplaced(put_in(length, dep)).has_value();
  }
  const Dependents for_strands =
      !unplaced_strand || !st.for_all.problem.empty() ? st.for_all : dependents(m, st.s, st.sol, st.spec, with_strands);
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
}

}  // namespace

std::optional<Motion> analyze_motion(const Model& m, const EquationSystem& s, const Solution& sol) {
  if (!m.motion) return std::nullopt;
  const MotionSpec& spec = *m.motion;
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
  MotionStory st{m, s, sol, spec, *m.symbols, out, eom};
  if (!take_accelerations(st)) return out;
  // The dependent coordinates are needed wherever the motion follows something: the
  // accelerations (without them there is no motion), then the quantities asked for and the
  // validity conditions (a string's T >= 0 in the spring end x_S = 2 x + C of a string over a
  // movable pulley); what cannot be followed is said, never dropped.
  st.for_accelerations = dependents(m, s, sol, spec, st.all);
  if (!st.for_accelerations.problem.empty()) {
    out.problem = st.for_accelerations.problem;
    return out;
  }
  if (!initial_rates_agree(st)) return out;
  place_dependents(st);
  if (!accelerations_in_state(st)) return out;

  const LinearForm lf = linear_form(st);
  mass_matrix(st);
  // A mass matrix that turns with the coordinates (coupled links): the equations also as a
  // person writes them, M(q) q'' = F.
  const std::size_t n = eom.dof;
  if (!st.mass_constant && n > 1) take_mass_form(m, eom);
  if (eom.linear) stiffness_and_damping(st, lf);
  if (eom.linear && n > 1) natural_frequencies(st);

  // One degree of freedom, linear: the response in closed form.
  if (n == 1 && eom.linear) {
    closed_form_response(st);
  } else if (!eom.linear) {
    out.no_response = "the equation of motion is nonlinear (" + eom.nonlinear + "; simulate it)";
    eom.linearised = n == 1 ? linearised(m, eom) : linearised_system(m, eom);
  } else {
    out.no_response = std::to_string(n) + " degrees of freedom (the modes are numeric; simulate the motion)";
  }
  // The speed at a position, from the work-energy balance.
  if (spec.speed_at) out.energy = work_energy(m, eom, spec, st.mass_constant);

  quantities_in_state(st);
  conditions_in_state(st);
  strands_in_state(st);
  for (const auto& slip : m.slips) out.slips_in_state.emplace_back(slip.source, put_in(slip.speed, *st.dep));
  if (!m.direction_assumed_by.empty()) out.direction_against = against_at_start(m, sol, *st.dep, spec);
  if (!out.response) return out;

  along_response(st);
  return out;
}

}  // namespace tackle
