#include "motion/mass_form.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <unordered_map>

#include <Eigen/Dense>

#include "expr/print.hpp"
#include "expr/rational.hpp"
#include "expr/trig.hpp"
#include "model/kinematics.hpp"
#include "motion/motion.hpp"
#include "numeric/evaluate.hpp"

namespace tackle {

using namespace GiNaC;

namespace {

// A term of an expanded sum split as number * rest * (one sine or cosine of A) * (one of B),
// A and B two different arguments in text order; nothing when it is not of that shape.
struct TrigPair {
  numeric coefficient = 1;
  ex rest = 1;
  ex a, b;
  bool sin_a = false, sin_b = false;
};

std::optional<TrigPair> trig_pair(const ex& term) {
  TrigPair p;
  std::vector<ex> trig;
  const std::size_t k = is_a<mul>(term) ? term.nops() : 1;
  for (std::size_t i = 0; i < k; ++i) {
    const ex f = is_a<mul>(term) ? term.op(i) : term;
    if (is_a<numeric>(f))
      p.coefficient *= ex_to<numeric>(f);
    else if (is_ex_the_function(f, sin) || is_ex_the_function(f, cos))
      trig.push_back(f);
    else
      p.rest *= f;
  }
  if (trig.size() != 2 || trig[0].op(0).is_equal(trig[1].op(0))) return std::nullopt;
  if (to_text(trig[1].op(0)) < to_text(trig[0].op(0))) std::swap(trig[0], trig[1]);
  p.a = trig[0].op(0), p.b = trig[1].op(0);
  p.sin_a = is_ex_the_function(trig[0], sin), p.sin_b = is_ex_the_function(trig[1], sin);
  return p;
}

// cos(a) cos(b) + sin(a) sin(b) = cos(a - b) and sin(a) cos(b) - cos(a) sin(b) = sin(a - b),
// where an expanded sum has such pairs of terms with equal coefficients (a chain's mass
// matrix, l^2 m cos(theta_1 - theta_2), as a person writes it). Anything else stays.
ex angle_differences(const ex& e) {
  if (!is_a<add>(e)) return e;
  struct Group {
    ex rest, a, b;
    numeric cc = 0, ss = 0, sc = 0, cs = 0;  // cos a cos b, sin a sin b, sin a cos b, cos a sin b
  };
  std::map<std::string, Group> groups;  // by the rest and the arguments' text: the same order in every run
  ex out = 0;
  for (std::size_t i = 0; i < e.nops(); ++i) {
    const auto p = trig_pair(e.op(i));
    if (!p) {
      out += e.op(i);
      continue;
    }
    Group& g = groups[to_text(p->rest) + "|" + to_text(p->a) + "|" + to_text(p->b)];
    g.rest = p->rest, g.a = p->a, g.b = p->b;
    (p->sin_a ? (p->sin_b ? g.ss : g.sc) : (p->sin_b ? g.cs : g.cc)) += p->coefficient;
  }
  for (auto& [key, g] : groups) {
    const ex ca = cos(g.a), sa = sin(g.a), cb = cos(g.b), sb = sin(g.b);
    if (g.cc == g.ss)
      out += g.cc * g.rest * cos(g.a - g.b);
    else
      out += g.rest * (g.cc * ca * cb + g.ss * sa * sb);
    if (g.sc == -g.cs)
      out += g.sc * g.rest * sin(g.a - g.b);
    else
      out += g.rest * (g.sc * sa * cb + g.cs * ca * sb);
  }
  return out;
}

// The loads on each body, by the body's index.
std::vector<std::vector<const Load*>> loads_by_body(const Model& m) {
  std::vector<std::vector<const Load*>> out(m.bodies.size());
  for (const auto& l : m.loads)
    if (l.body >= 0) out[static_cast<std::size_t>(l.body)].push_back(&l);
  return out;
}

// Each coordinate's balance, sum of (m a . dv/dq'_i + I alpha dw/dq'_i - the loads' virtual
// power), expanded: 0 along every motion the coordinates allow.
std::vector<ex> projected_balances(const Model& m) {
  const MotionSpec& s = *m.motion;
  const auto loads = loads_by_body(m);
  std::vector<ex> balance(s.coordinates.size(), 0);
  for (std::size_t k = 0; k < m.bodies.size(); ++k) {
    const Body& b = m.bodies[k];
    const auto v = kinematics::velocity(m, b);
    if (!v) continue;  // at rest: no virtual power
    const ex w = kinematics::omega(m, b);
    for (std::size_t i = 0; i < s.rates.size(); ++i) {
      const symbol& rate = ex_to<symbol>(s.rates[i]);
      const Vec pv{(*v)[0].diff(rate), (*v)[1].diff(rate), (*v)[2].diff(rate)};
      const ex pw = w.diff(rate);
      if (pv[0].is_zero() && pv[1].is_zero() && pv[2].is_zero() && pw.is_zero()) continue;
      ex sum = b.has_mass ? kinematics::kinetic_energy_rate(m, b, pv, pw) : ex(0);
      for (const Load* l : loads[k]) sum -= kinematics::power(b, *l, pv, pw);
      balance[i] += sum.expand();
    }
  }
  return balance;
}

// An expanded balance linear in the accelerations as sum_j c_j a_j + rest: (c, rest), in one
// pass over its terms (a derivative per acceleration walks them all n times, and GiNaC's
// derivative of every sine throws and catches inside). Nothing when a term holds an
// acceleration other than to the first power, or two.
std::optional<std::pair<std::vector<ex>, ex>> by_acceleration(const ex& balance, const std::vector<ex>& accelerations) {
  std::unordered_map<ex, std::size_t, ExHash, ex_is_equal> index;
  for (std::size_t j = 0; j < accelerations.size(); ++j) index.emplace(accelerations[j], j);
  std::vector<exvector> coefficients(accelerations.size());
  exvector rest;
  const std::size_t terms = is_a<add>(balance) ? balance.nops() : 1;
  for (std::size_t t = 0; t < terms; ++t) {
    const ex term = is_a<add>(balance) ? balance.op(t) : balance;
    const std::size_t k = is_a<mul>(term) ? term.nops() : 1;
    std::optional<std::size_t> which;
    exvector others;
    for (std::size_t i = 0; i < k; ++i) {
      const ex f = is_a<mul>(term) ? term.op(i) : term;
      const auto it = index.find(f);
      if (it != index.end() && !which)
        which = it->second;
      else if (it != index.end() || (is_a<power>(f) && index.count(f.op(0))))
        return std::nullopt;
      else
        others.push_back(f);
    }
    (which ? coefficients[*which] : rest).push_back(mul(others));
  }
  std::vector<ex> row;
  for (const auto& c : coefficients) row.push_back(add(c));
  return std::make_pair(row, ex(add(rest)));
}

}  // namespace

std::optional<MassForm> mass_form(const Model& m, std::string& why_not) {
  if (!m.motion) return std::nullopt;
  const MotionSpec& s = *m.motion;
  for (const auto& c : m.coordinates)
    if (!contains(s.coordinates, c.q)) {
      why_not = "the coordinate " + to_text(c.q) + " is tied to the motion's coordinates";
      return std::nullopt;
    }
  const std::vector<ex> balance = projected_balances(m);
  const std::size_t n = balance.size();
  for (const auto& u : m.candidates)
    if (!contains(s.accelerations, u) &&
        std::any_of(balance.begin(), balance.end(), [&](const ex& e) { return e.has(u); })) {
      why_not = to_text(u) + " does work on the motion the coordinates allow";
      return std::nullopt;
    }
  MassForm f;
  f.M = matrix(static_cast<unsigned>(n), static_cast<unsigned>(n));
  for (std::size_t i = 0; i < n; ++i) {
    const auto row = by_acceleration(balance[i], s.accelerations);
    if (!row) {
      why_not = "the balances are not linear in the accelerations";
      return std::nullopt;
    }
    for (std::size_t j = 0; j < n; ++j) {
      const ex entry = angle_differences(fewer_trig_terms(row->first[j]));
      f.M(static_cast<unsigned>(i), static_cast<unsigned>(j)) = entry;
      f.mass_varies = f.mass_varies || std::any_of(s.coordinates.begin(), s.coordinates.end(),
                                                   [&](const ex& q) { return entry.has(q); });
    }
    f.F.push_back(angle_differences(fewer_trig_terms(-row->second)));
  }
  return f;
}

LeftToMotion instant_left_to_motion(const Model& m) {
  if (!m.motion || m.motion->coordinates.size() < 2 || !m.wanted.empty() || m.interval || m.impact) return {};
  const exmap values = m.symbols->values();
  for (const auto& g : m.given)
    if (values.count(g)) return {};  // a state of the instant is given: it is asked about
  std::string why_not;
  auto f = mass_form(m, why_not);
  if (!f || !f->mass_varies) return {};
  const std::string n = std::to_string(m.motion->coordinates.size());
  return {
      "nothing is asked at the instant (no 'find', no 'given'), and its accelerations in closed form would be ratios "
      "of "
      "determinants of the " +
          n + " x " + n +
          " mass matrix, which turns with the coordinates; the motion below has its equations from these balances "
          "with the joint forces eliminated (projected on each coordinate)",
      std::make_shared<const MassForm>(std::move(*f))};
}

std::optional<MassFormAtRest> at_rest(const Model& m, const MassForm& f) {
  const MotionSpec& s = *m.motion;
  const std::size_t n = s.coordinates.size();
  exmap rest, roots;
  for (std::size_t i = 0; i < n; ++i) rest[s.coordinates[i]] = 0, rest[s.rates[i]] = 0;
  for (const auto& l : m.lengths) roots[l.symbol] = sqrt(l.squared);
  MassFormAtRest r;
  const auto size = static_cast<unsigned>(n);
  r.M0 = matrix(size, size), r.C0 = matrix(size, size), r.K0 = matrix(size, size);
  for (unsigned i = 0; i < size; ++i) {
    const ex Fi = roots.empty() ? f.F[i] : f.F[i].subs(roots);
    if (Fi.has(m.time) || !normal(Fi.subs(rest)).is_zero()) return std::nullopt;
    for (unsigned j = 0; j < size; ++j) {
      r.M0(i, j) = f.M(i, j).subs(rest);
      r.K0(i, j) = normal(-Fi.diff(ex_to<symbol>(s.coordinates[j])).subs(rest));
      r.C0(i, j) = normal(-Fi.diff(ex_to<symbol>(s.rates[j])).subs(rest));
    }
  }
  return r;
}

std::optional<std::vector<double>> small_oscillations(const Model& m, const matrix& K) {
  const auto n = static_cast<Eigen::Index>(K.rows());
  const exmap values = m.symbols->values();
  Eigen::MatrixXd Kn(n, n);
  for (Eigen::Index i = 0; i < n; ++i)
    for (Eigen::Index j = 0; j < n; ++j) {
      ex kij = K(static_cast<unsigned>(i), static_cast<unsigned>(j));
      for (int depth = 0; depth < 8 && !kij.is_zero(); ++depth) kij = substituted(kij, m.symbols->definitions());
      const auto v = kij.is_zero() ? std::optional<double>(0) : NormalForm(kij).approx_at(values);
      if (!v) return std::vector<double>{};  // no numbers: the matrix alone
      Kn(i, j) = *v;
    }
  const Eigen::EigenSolver<Eigen::MatrixXd> es(Kn);
  if (es.info() != Eigen::Success) return std::vector<double>{};
  const double scale = Kn.cwiseAbs().maxCoeff();
  std::vector<double> out;
  for (Eigen::Index i = 0; i < es.eigenvalues().size(); ++i) {
    const auto ev = es.eigenvalues()(i);
    // A zero eigenvalue is a free mode (a cart that rolls on with no spring): frequency 0.
    const double tiny = 1e-12 * (1 + scale);
    if (std::abs(ev.imag()) > 1e-9 * (1 + std::abs(ev.real())) || ev.real() < -tiny)
      return std::nullopt;  // not a stable rest
    out.push_back(ev.real() <= tiny ? 0.0 : std::sqrt(ev.real()));
  }
  std::sort(out.begin(), out.end());
  return out;
}

bool take_mass_form(const Model& m, EquationsOfMotion& eom, std::shared_ptr<const MassForm> made) {
  if (!made) {
    std::string why_not;
    auto f = mass_form(m, why_not);
    if (!f || !f->mass_varies) return false;
    made = std::make_shared<const MassForm>(std::move(*f));
  }
  eom.mass_form = true;
  eom.linear = false;
  eom.nonlinear = "the mass matrix changes with the coordinates";
  eom.M = made->M;
  eom.forcing = made->F;
  return true;
}

void follow_mass_form(const Model& m, const std::shared_ptr<const MassForm>& f, Motion& out) {
  EquationsOfMotion& eom = out.eom;
  take_mass_form(m, eom, f);
  out.no_response = "the equations of motion are nonlinear (" + eom.nonlinear + "; simulate them)";
  for (const auto& c : m.conditions)
    out.not_followed.emplace_back(c.source, "its forces are not solved for, as nothing is asked at the instant");
  const auto rest = at_rest(m, *f);
  if (!rest) return;
  for (unsigned i = 0; i < rest->C0.rows(); ++i)
    for (unsigned j = 0; j < rest->C0.cols(); ++j)
      if (!rest->C0(i, j).is_zero()) return;  // damped: not the undamped modes
  EquationsOfMotion::Linearised lin;
  lin.about = 0;
  lin.stiffness_matrix = rest->M0.inverse().mul(rest->K0);
  for (unsigned i = 0; i < lin.stiffness_matrix.rows(); ++i)
    for (unsigned j = 0; j < lin.stiffness_matrix.cols(); ++j)
      lin.stiffness_matrix(i, j) = normal(lin.stiffness_matrix(i, j));
  const auto frequencies = small_oscillations(m, lin.stiffness_matrix);
  if (!frequencies) return;  // not a stable rest
  lin.frequencies = *frequencies;
  eom.linearised = lin;
}

}  // namespace tackle
