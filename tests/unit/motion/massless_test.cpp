// Massless bodies joining strings and springs (issue 30, "right or refused"): each coordinate
// of a massless body follows from its balance and the constraints, and every validity
// condition is followed in time through the constraints. Expected values by hand, and the
// motion by an independent Runge-Kutta integration of the hand-derived equation.
#include <catch2/catch.hpp>

#include <cmath>
#include <functional>

#include "motion/simulate.hpp"
#include "numeric/evaluate.hpp"
#include "../../support/helpers.hpp"

using namespace tackle;
using namespace tackle::test;
using namespace GiNaC;

namespace {

// Block A (mass m) on a smooth table, x along it; a string from A over the pulley P at
// (L, 0) down to a massless ring R at (L, y_R), which slides in a smooth vertical slot; a
// spring (k, l_0) from R to the anchor G at (2 L, -H), so its strand turns as R moves.
const std::string ring = R"(title: block, string over a pulley, massless ring, spring at an angle
axes: [x, y]
parameters:
  m: {value: 2, unit: kg}
  g: {value: 9.81, unit: m/s^2}
  k: {value: 200, unit: N/m}
  L: {value: 1, unit: m}
  H: {value: 1, unit: m}
  l_0: {value: 0.2, unit: m}
gravity: [0, -g]
bodies:
  A: {mass: m, position: x, center_of_mass: [x, 0]}
  R: {mass: 0, position: y_R, center_of_mass: [L, y_R]}
points:
  P: [L, 0]
  G: [2*L, -H]
connections:
  - {type: pulley, at: P}
  - {type: roller, body: A, at: A, normal: [0, 1]}
  - {type: roller, body: R, at: R, normal: [-1, 0]}
  - {type: spring, name: sp, path: [R, G], k: k, rest_length: l_0}
strings:
  - {name: s, path: [A, P, R], tension: T}
layout: {x: 0, y_R: -0.5}
)";

// By hand: the ring's balance along y, T = k (l - l_0) (H + y_R)/l with the spring's length
// l = sqrt(L^2 + (H + y_R)^2); A's, m x'' = T; the string keeps (L - x) - y_R, so with
// x(0) = 0 and y_R(0) = -1/2, y_R = -1/2 - x.
double tension(double y_R) {
  const double k = 200, L = 1, H = 1, l_0 = 0.2;
  const double l = std::sqrt(L * L + (H + y_R) * (H + y_R));
  return k * (l - l_0) * (H + y_R) / l;
}

// Classical Runge-Kutta of m x'' = T(y_R = -1/2 - x) from rest at x = 0, to time t.
std::pair<double, double> integrate(double until) {
  const double m = 2;
  auto f = [&](double x) { return tension(-0.5 - x) / m; };
  double x = 0, v = 0;
  const int steps = 20000;
  const double h = until / steps;
  for (int i = 0; i < steps; ++i) {
    const double k1x = v, k1v = f(x);
    const double k2x = v + h / 2 * k1v, k2v = f(x + h / 2 * k1x);
    const double k3x = v + h / 2 * k2v, k3v = f(x + h / 2 * k2x);
    const double k4x = v + h * k3v, k4v = f(x + h * k3x);
    x += h / 6 * (k1x + 2 * k2x + 2 * k3x + k4x);
    v += h / 6 * (k1v + 2 * k2v + 2 * k3v + k4v);
  }
  return {x, v};
}

double number(const ex& e, const SymbolTable& t, const exmap& also = {}) {
  ex v = e;
  const exmap defs = t.definitions(true);
  for (int depth = 0; depth < 8; ++depth) v = v.subs(defs, subs_options::no_pattern);
  v = v.subs(also, subs_options::no_pattern).subs(t.values(), subs_options::no_pattern);
  return ex_to<numeric>(evalf(v)).to_double();
}

}  // namespace

TEST_CASE("Massless ring: at one instant the ring's balance gives the tension from the turning spring", "[motion][massless][trust]") {
  const auto a = run_text(ring + "find: [T, ddot(x), ddot(y_R)]\n");
  const Derivation d = explain(*a);
  REQUIRE(d.answers.size() == 3);
  const SymbolTable& t = *a->model.symbols;
  for (const auto& ans : d.answers) REQUIRE(ans.closed_form);
  // At y_R = -0.3 (any position: it is the state at the instant).
  const exmap at{{t.find("y_R")->sym, numeric(-3, 10)}};
  const double T = tension(-0.3);
  CHECK(number(*d.answers[0].closed_form, t, at) == Approx(T).epsilon(1e-12));
  CHECK(number(*d.answers[1].closed_form, t, at) == Approx(T / 2).epsilon(1e-12));
  CHECK(number(*d.answers[2].closed_form, t, at) == Approx(-T / 2).epsilon(1e-12));
  CHECK(d.status == "determined");
}

TEST_CASE("Massless ring: the motion follows the ring through the string, not its starting place", "[motion][massless][trust]") {
  const auto a = run_text(ring + "find: [T]\nmotion:\n  initial: {x: 0, dot(x): 0, y_R: -0.5}\n  until: 0.1\n");
  REQUIRE(a->motion);
  REQUIRE(a->motion->problem.empty());
  SimulationSpec spec;
  spec.plot = {"x", "y_R", "T"};
  spec.samples = 3;
  const Simulation s = simulate(*a, spec, Location{"t.yaml", 1, 1});
  REQUIRE(s.complete);
  const auto [x, v] = integrate(0.1);
  (void)v;
  REQUIRE(s.table.y.size() == 3);
  CHECK(*s.table.y[0].back() == Approx(x).epsilon(1e-7));
  CHECK(*s.table.y[1].back() == Approx(-0.5 - x).epsilon(1e-7));
  CHECK(*s.table.y[2].back() == Approx(tension(-0.5 - x)).epsilon(1e-7));
  // The ring moved: the tension is not the starting one.
  CHECK(std::abs(*s.table.y[2].back() - tension(-0.5)) > 1);
}

TEST_CASE("Massless ring: the string goes slack when the spring lies level with the ring", "[motion][massless][trust]") {
  // T = 0 where H + y_R = 0: y_R = -1, so x = 1/2. The independent integration gives the time.
  const auto a = run_text(ring + "motion:\n  initial: {x: 0, dot(x): 0, y_R: -0.5}\n  until: 1\n");
  REQUIRE(a->motion);
  const Simulation s = simulate(*a, SimulationSpec{}, Location{"t.yaml", 1, 1});
  REQUIRE(!s.complete);
  REQUIRE(!s.events.empty());
  CHECK(s.events.back().what == "string s: the string goes slack");
  // Bisect the hand integration for x = 1/2.
  double lo = 0, hi = 1;
  for (int i = 0; i < 40; ++i) ((integrate((lo + hi) / 2).first < 0.5) ? lo : hi) = (lo + hi) / 2;
  CHECK(s.events.back().t == Approx(lo).epsilon(1e-6));
}

TEST_CASE("Movable pulley: the string's condition is followed in time through x_S = 2 x + C", "[motion][massless][trust]") {
  // Block A (m) pushed by F carries a pulley; the string runs from the wall W round the pulley
  // back to the massless end S of a spring (k, l_0) anchored at Q = -D. By hand: the string
  // keeps 2 x - x_S; S's balance, T = k (D + x_S - l_0); A's, m x'' = F - 2 T. From x = 1,
  // x_S = 1/2 at rest: x_S = 2 x - 3/2, the equilibrium 2 T = F, and T(t) = F/2 + a cos(lambda t)
  // with lambda = 2 sqrt(k/m) and a = 2 k (1 - x_eq), x_eq = (F + 3 k + 2 k l_0 - 2 D k)/(4 k).
  const auto a = run_text(R"(title: movable pulley and a spring end
axes: [x]
parameters:
  m: {value: 2, unit: kg}
  k: {value: 200, unit: N/m}
  F: {value: 10, unit: N}
  l_0: {value: 0.2, unit: m}
  D: {value: 1, unit: m}
bodies:
  A: {mass: m, position: x}
  S: {mass: 0, position: x_S}
points:
  W: 0
  Q: -D
  pA: {on: A}
loads:
  - {on: A, force: F}
strings:
  - {name: s, path: [W, pA, S], tension: T}
connections:
  - {type: spring, name: sp, path: [Q, S], k: k, rest_length: l_0}
layout: {x: 1, x_S: 0.5}
find: [T]
motion:
  initial: {x: 1, dot(x): 0, x_S: 0.5}
  until: 1
)");
  REQUIRE(a->motion);
  REQUIRE(a->motion->response);
  REQUIRE(a->motion->conditions.size() == 1);
  const ConditionInTime& c = a->motion->conditions[0];
  CHECK(c.condition.source == "string s");
  const SymbolTable& t = *a->model.symbols;
  const double k = 200, m = 2, F = 10, l_0 = 0.2, D = 1;
  const double x_eq = (F + 3 * k + 2 * k * l_0 - 2 * D * k) / (4 * k), amp = 2 * k * (1 - x_eq), lambda = 2 * std::sqrt(k / m);
  const exmap lambda_value{{a->model.motion->lambda, numeric(20)}};
  for (const double time : {0.0, 0.013, 0.05}) {
    const exmap at{{a->model.time, numeric(time)}, {a->model.motion->lambda, numeric(20)}};
    CHECK(number(c.of_t, t, at) == Approx(F / 2 + amp * std::cos(lambda * time)).epsilon(1e-9));
  }
  REQUIRE(c.extreme);
  CHECK(number(*c.extreme, t, lambda_value) == Approx(F / 2 - std::abs(amp)).epsilon(1e-9));
  REQUIRE(c.holds_for_all_t);
  CHECK(*c.holds_for_all_t == false);
  // T(t) is reported along the response too.
  REQUIRE(a->motion->quantities.size() == 1);
  CHECK(number(a->motion->quantities[0].of_t, t, {{a->model.time, numeric(0)}, {a->model.motion->lambda, numeric(20)}}) ==
        Approx(F / 2 + amp).epsilon(1e-9));
}
