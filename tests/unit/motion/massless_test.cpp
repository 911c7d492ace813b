// Massless bodies joining strings and springs (issue 30, "right or refused"): each coordinate
// of a massless body follows from its balance and the constraints, and every validity
// condition is followed in time through the constraints. Expected values by hand, and the
// motion by an independent Runge-Kutta integration of the hand-derived equation.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <functional>

#include "motion/simulate.hpp"
#include "numeric/evaluate.hpp"
#include "report/derivation.hpp"
#include "solve/solve.hpp"
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

}  // namespace

TEST_CASE("Massless ring: at one instant the ring's balance gives the tension from the turning spring",
          "[motion][massless][trust]") {
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

TEST_CASE("Massless ring: the motion follows the ring through the string, not its starting place",
          "[motion][massless][trust]") {
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

TEST_CASE("Massless ring: the string goes slack when the spring lies level with the ring",
          "[motion][massless][trust]") {
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

TEST_CASE("Movable pulley: the string's condition is followed in time through x_S = 2 x + C",
          "[motion][massless][trust]") {
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
  const double x_eq = (F + 3 * k + 2 * k * l_0 - 2 * D * k) / (4 * k), amp = 2 * k * (1 - x_eq),
               lambda = 2 * std::sqrt(k / m);
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
  CHECK(
      number(a->motion->quantities[0].of_t, t, {{a->model.time, numeric(0)}, {a->model.motion->lambda, numeric(20)}}) ==
      Approx(F / 2 + amp).epsilon(1e-9));
}

namespace {

// Block A (m) on a spring k_1 (rest l_1) from the massless joint S, which hangs on a spring
// k_2 (rest l_2) from the wall W at 0: two springs in series. No constraint ties x_S.
const std::string in_series = R"(title: two springs in series through a massless joint
axes: [x]
parameters:
  m: {value: 2, unit: kg}
  k_1: {value: 100, unit: N/m}
  k_2: {value: 300, unit: N/m}
  l_1: {value: 0.5, unit: m}
  l_2: {value: 0.5, unit: m}
bodies:
  A: {mass: m, position: x}
  S: {mass: 0, position: x_S}
points:
  W: 0
connections:
  - {type: spring, name: sp2, path: [W, S], k: k_2, rest_length: l_2}
  - {type: spring, name: sp1, path: [S, A], k: k_1, rest_length: l_1}
layout: {x: 1.2, x_S: 0.6}
)";

}  // namespace

TEST_CASE("Springs in series: the massless joint's coordinate follows from its balance", "[motion][massless][trust]") {
  // By hand: S's balance, k_1 (x - x_S - l_1) = k_2 (x_S - l_2), gives x_S; A's,
  // m x'' = -k_1 (x - x_S - l_1) = -k (x - l_1 - l_2) with the in_series stiffness
  // k = k_1 k_2/(k_1 + k_2). (Before, the balance of S was called inconsistent.)
  const auto a = run_text(in_series + "find: [x_S, ddot(x)]\n");
  const Derivation d = explain(*a);
  REQUIRE(d.answers.size() == 2);
  REQUIRE(d.answers[0].closed_form);
  REQUIRE(d.answers[1].closed_form);
  const SymbolTable& t = *a->model.symbols;
  const ex m = t.find("m")->sym, k_1 = t.find("k_1")->sym, k_2 = t.find("k_2")->sym, l_1 = t.find("l_1")->sym,
           l_2 = t.find("l_2")->sym, x = t.find("x")->sym;
  CHECK(normal(*d.answers[0].closed_form - (k_1 * (x - l_1) + k_2 * l_2) / (k_1 + k_2)).is_zero());
  CHECK(normal(*d.answers[1].closed_form + k_1 * k_2 / (k_1 + k_2) * (x - l_1 - l_2) / m).is_zero());
  CHECK(d.status == "determined");
}

TEST_CASE("Springs in series: the motion has one degree of freedom with the in_series stiffness",
          "[motion][massless][trust]") {
  // m x'' + k x = k (l_1 + l_2), k = k_1 k_2/(k_1 + k_2) = 75 N/m: lambda = sqrt(37.5) rad/s, and
  // from rest at x = 1.2 m, x(t) = 1 + 0.2 cos(lambda t).
  const auto a = run_text(in_series + "motion:\n  initial: {x: 1.2, dot(x): 0}\n  until: 1\n");
  REQUIRE(a->motion);
  REQUIRE(a->motion->problem.empty());
  const EquationsOfMotion& eom = a->motion->eom;
  CHECK(eom.dof == 1);
  REQUIRE(eom.linear);
  const SymbolTable& t = *a->model.symbols;
  CHECK(number(eom.K(0, 0), t) == Approx(75).epsilon(1e-12));
  CHECK(number(eom.M(0, 0), t) == Approx(2).epsilon(1e-12));
  REQUIRE(a->motion->response);
  for (const double time : {0.0, 0.3, 0.71}) {
    const exmap at{{a->model.time, numeric(time)}, {a->model.motion->lambda, sqrt(numeric(75, 2))}};
    CHECK(number(a->motion->response->q, t, at) == Approx(1 + 0.2 * std::cos(std::sqrt(37.5) * time)).epsilon(1e-12));
  }
  const Simulation s = simulate(*a, SimulationSpec{0.71, {"x", "x_S"}, 2}, Location{"t.yaml", 1, 1});
  REQUIRE(s.complete);
  const double x = 1 + 0.2 * std::cos(std::sqrt(37.5) * 0.71);
  CHECK(*s.table.y[0].back() == Approx(x).epsilon(1e-8));
  CHECK(*s.table.y[1].back() == Approx((100 * (x - 0.5) + 300 * 0.5) / 400).epsilon(1e-8));
}

TEST_CASE("Springs in series: a massless body's starting place is not asked for, and a turning strand is refused",
          "[motion][massless][errors]") {
  CHECK(errors_of(in_series + "motion:\n  initial: {x: 1.2, dot(x): 0, x_S: 0.6}\n") ==
        std::vector<std::string>{
            "t.yaml:19:32: initial value of 'x_S': body 'S' has no mass, so its balance gives it at every "
            "instant (expected initial values of the motion's coordinates only)"});
  // A massless ring in a vertical slot pulled down by a load and up by a spring at an angle:
  // its balance is not linear in y_R.
  CHECK(errors_of(R"(title: ring on a spring at an angle
axes: [x, y]
parameters:
  F: {value: 10, unit: N}
  k: {value: 100, unit: N/m}
  l_0: {value: 0.5, unit: m}
  L: {value: 1, unit: m}
bodies:
  R: {mass: 0, position: y_R, center_of_mass: [0, y_R]}
points:
  G: [L, 0]
loads:
  - {on: R, at: R, force: [0, -F]}
connections:
  - {type: roller, body: R, at: R, normal: [1, 0]}
  - {type: spring, name: sp, path: [R, G], k: k, rest_length: l_0}
layout: {y_R: -0.5}
)") == std::vector<std::string>{
           "t.yaml:9:3: body 'R' has no mass and no constraint ties y_R to the other coordinates, so its "
           "balance fixes it; but a strand that turns with it makes that balance nonlinear in y_R "
           "(expected a string or a joint that ties it, or a mass)"});
}

TEST_CASE("Strands: a block pulled into its pulley ends the motion with an event (issue 30)", "[motion][trust]") {
  // Block A (m_A) on a smooth table from x = 0, pulled over the pulley P at x = L = 1 m by the
  // hanging block B (m_B): a = m_B g/(m_A + m_B) = 9.81/3 m/s^2 from rest, so A reaches the
  // pulley when a t^2/2 = L: t = sqrt(2 L/a). The strand A-P then has no length left.
  const auto a = run_text(R"(title: block pulled into its pulley
axes: [x, y]
parameters:
  m_A: {value: 2, unit: kg}
  m_B: {value: 1, unit: kg}
  g: {value: 9.81, unit: m/s^2}
  L: {value: 1, unit: m}
gravity: [0, -g]
bodies:
  A: {mass: m_A, position: x, center_of_mass: [x, 0]}
  B: {mass: m_B, position: y, center_of_mass: [L, y]}
points:
  P: [L, 0]
connections:
  - {type: pulley, at: P}
  - {type: roller, body: A, at: A, normal: [0, 1]}
strings:
  - {name: s, path: [A, P, B], tension: T}
layout: {x: 0, y: -0.5}
motion:
  initial: {x: 0, dot(x): 0, y: -0.5}
  until: 2
)");
  REQUIRE(a->motion);
  const Simulation s = simulate(*a, SimulationSpec{}, Location{"t.yaml", 1, 1});
  REQUIRE(!s.complete);
  REQUIRE(s.events.size() == 1);
  CHECK(s.events[0].what == "strand A-P of string s: its length reaches zero (a body reaches the point at its end)");
  CHECK(s.events[0].t == Approx(std::sqrt(2 / (9.81 / 3))).epsilon(1e-8));
}

TEST_CASE("Massless ring: the motion is described by the coordinate 'initial' gives, not the first body's",
          "[motion][massless]") {
  // The ring listed first; `initial` gives the block's x and dot(x) (and y_R, which fixes the
  // string's length): the motion is described by x, and initial values are accepted as given.
  std::string yaml = ring;
  const std::string a_line = "  A: {mass: m, position: x, center_of_mass: [x, 0]}\n";
  const std::string r_line = "  R: {mass: 0, position: y_R, center_of_mass: [L, y_R]}\n";
  yaml.replace(yaml.find(a_line), a_line.size() + r_line.size(), r_line + a_line);
  const auto a = run_text(yaml + "motion:\n  initial: {x: 0, dot(x): 0, y_R: -0.5}\n  until: 0.1\n");
  REQUIRE(a->motion);
  REQUIRE(a->motion->eom.q.size() == 1);
  CHECK(to_text(a->motion->eom.q[0]) == "x");
}

namespace {

// Issue 42, item 3: examples/string-and-spring-at-a-massless-ring-forced.yaml. Block A (m) on
// a smooth table at (x, 0), pulled back by -P - F_0 cos(w t); the string from A over the pulley
// P_1 at (L, 0) straight down to the massless ring S at (L, y_S); a spring (k, l_0) from S down
// to G at (L, -H). By hand: the string keeps (L - x) - y_S, so y_S = y_0 - x from x(0) = 0;
// S's balance, T = k (y_S + H - l_0); A's, m x'' + k x = k (y_0 + H - l_0) - P - F_0 cos(w t).
// With m = 2, k = 200, P = 20, F_0 = 10, w = 5, H = 1, l_0 = 0.5, y_0 = -0.3: lambda = 10,
// x_e = 0.1, X = -F_0/(k - m w^2) = -1/15, and from rest at 0,
// x(t) = 0.1 - cos(5 t)/15 - cos(10 t)/30, y_S = -0.3 - x, T = 200 (0.2 - x).
const std::string driven_ring = "string-and-spring-at-a-massless-ring-forced.yaml";

double driven_x(double t) { return 0.1 - std::cos(5 * t) / 15 - std::cos(10 * t) / 30; }

// The string's T >= 0 along the closed-form response.
const ConditionInTime* string_in_time(const Analysis& a) {
  REQUIRE(a.motion);
  REQUIRE(a.motion->response);
  const auto c = std::find_if(a.motion->conditions.begin(), a.motion->conditions.end(),
                              [](const ConditionInTime& x) { return x.condition.source == "string s"; });
  REQUIRE(c != a.motion->conditions.end());
  return &*c;
}

}  // namespace

TEST_CASE("Massless ring: the spring acts on a driven block through the string and the ring, in time (2-D)",
          "[motion][massless][trust]") {
  const auto a = run_text(read_example(driven_ring));
  REQUIRE(a->motion);
  REQUIRE(a->motion->problem.empty());
  const EquationsOfMotion& eom = a->motion->eom;
  REQUIRE(eom.dof == 1);
  CHECK(to_text(eom.q[0]) == "x");
  REQUIRE(eom.linear);
  const SymbolTable& t = *a->model.symbols;
  const ex m = t.find("m")->sym, k = t.find("k")->sym, P = t.find("P")->sym, F_0 = t.find("F_0")->sym,
           w = t.find("w")->sym, H = t.find("H")->sym, l_0 = t.find("l_0")->sym, y_0 = t.find("y_0")->sym,
           time = a->model.time;
  // The stiffness is the spring's (not 0, as when the ring was held at its start).
  CHECK(normal(eom.M(0, 0) - m).is_zero());
  CHECK(normal(eom.K(0, 0) - k).is_zero());
  CHECK(normal(eom.forcing[0] - (k * (y_0 + H - l_0) - P - F_0 * cos(w * time))).is_zero());
  REQUIRE(a->motion->response);
  CHECK(a->motion->response->verified);
  for (const double tt : {0.0, 0.3, 1.0}) {
    const exmap at{{time, numeric(tt)}, {a->model.motion->lambda, numeric(10)}};
    CHECK(number(a->motion->response->q, t, at) == Approx(driven_x(tt)).epsilon(1e-12).margin(1e-14));
  }
  // simulate follows the same motion: x, the ring's y_S = -0.3 - x and T = 200 (0.2 - x).
  for (const double tt : {0.3, 0.7, 1.0}) {
    INFO("t = " << tt);
    const Simulation s = simulate(*a, SimulationSpec{tt, {"x", "y_S", "T"}, 2}, Location{"t.yaml", 1, 1});
    REQUIRE(s.complete);
    const double x = driven_x(tt);
    CHECK(*s.table.y[0].back() == Approx(x).epsilon(1e-8));
    CHECK(*s.table.y[1].back() == Approx(-0.3 - x).epsilon(1e-8));
    CHECK(*s.table.y[2].back() == Approx(200 * (0.2 - x)).epsilon(1e-8));
  }
}

TEST_CASE("Massless ring: the string's steady-state condition goes through the ring's coordinate",
          "[motion][massless][trust]") {
  // T = P + k F_0/(k - m w^2) cos(w t) in the steady state: it holds for all t iff
  // P^2 (k - m w^2)^2 - k^2 F_0^2 >= 0, which fails in the band k (P - F_0)/(m P) < w^2 <
  // k (P + F_0)/(m P) (50 to 150 rad^2/s^2). Before, the condition kept y_S and read
  // k^2 (...)^2 >= 0, a condition that always holds, also where the string goes slack.
  auto check = [](const std::string& yaml, bool holds) {
    const auto a = run_text(yaml);
    const ConditionInTime* c = string_in_time(*a);
    const SymbolTable& t = *a->model.symbols;
    const ex m = t.find("m")->sym, k = t.find("k")->sym, P = t.find("P")->sym, F_0 = t.find("F_0")->sym,
             w = t.find("w")->sym;
    REQUIRE(c->steady_offset);
    CHECK(normal(*c->steady_offset - P).is_zero());
    REQUIRE(c->steady_amplitude_condition);
    CHECK_FALSE(c->steady_amplitude_condition->has(t.find("y_S")->sym));
    CHECK_FALSE(holds_always(*c->steady_amplitude_condition, ">=").has_value());
    const ex by_hand = pow(P, 2) * pow(k - m * pow(w, 2), 2) - pow(k, 2) * pow(F_0, 2);
    CHECK(normal(*c->steady_amplitude_condition - by_hand).is_zero());
    REQUIRE(c->band);
    CHECK(c->band->fails_between);
    CHECK(normal(c->band->low - k * (P - F_0) / (m * P)).is_zero());
    CHECK(normal(c->band->high - k * (P + F_0) / (m * P)).is_zero());
    REQUIRE(c->steady_holds);
    CHECK(*c->steady_holds == holds);
  };
  SECTION("w = 5 rad/s (w^2 = 25, below the band): the string stays taut") { check(read_example(driven_ring), true); }
  SECTION("w = 8 rad/s (w^2 = 64, in the band): the string goes slack in the steady state") {
    check(example_with(driven_ring, "w: {value: 5,", "w: {value: 8,"), false);
  }
}

TEST_CASE("Massless ring: a condition through the ring that always holds is said in words",
          "[motion][massless][report]") {
  // Undriven, from rest at x = 0 with the ring at y_S(0) = l_0 - H + P/(2 k) (the spring
  // stretched by P/(2 k)): T = k (y_S + H - l_0) = P/2 at the start, and with y_S = y_S(0) - x,
  // T = P/2 - k x and m x'' + k x = P/2 - P: x(t) = -P/(2 k) (1 - cos(lambda t)), so
  // T(t) = P - (P/2) cos(lambda t), least P/2 > 0 for every value of P (declared positive: a
  // force may be negative otherwise, and then P - sqrt(P^2)/2 >= 0 is a condition, P >= 0).
  std::string yaml = example_with(driven_ring, "\"-P - F_0*cos(w*t)\"", "\"-P\"");
  yaml = yaml.replace(yaml.find("y_S: y_0}"), 9, "y_S: l_0 - H + P/(2*k)}");
  yaml = yaml.replace(yaml.find("unit: N}"), 8, "unit: N, positive: true}");
  const auto a = run_text(yaml);
  const ConditionInTime* c = string_in_time(*a);
  const SymbolTable& t = *a->model.symbols;
  const ex P = t.find("P")->sym;
  REQUIRE(c->extreme);
  CHECK(normal(*c->extreme - P / 2).is_zero());
  const std::string text = write(explain(*a), Format::text, true);
  CHECK(text.find("Its least value over time, P/2, is never negative: this holds for every value of P.") !=
        std::string::npos);
  CHECK(text.find(">= 0    [least value over time]") == std::string::npos);
}

TEST_CASE("Massless ring: two springs in series oscillate at sqrt(k1 k2/(m (k1 + k2))) (2-D)",
          "[motion][massless][trust]") {
  // The springs in series on the x axis of a plane: block A on a smooth floor at (x, 0), the
  // massless ring S at (x_S, 0) between a spring k_2 (rest l_2) to the wall W at the origin and
  // a spring k_1 (rest l_1) to A. By hand: S's balance, k_1 (x - x_S - l_1) = k_2 (x_S - l_2),
  // at every instant; A's, m x'' = -k_1 (x - x_S - l_1) = -k (x - l_1 - l_2) with
  // k = k_1 k_2/(k_1 + k_2) = 75 N/m, lambda^2 = k/m = 37.5; from rest at 1.2 m,
  // x(t) = 1 + 0.2 cos(lambda t) and x_S = (100 (x - 0.5) + 150)/400.
  const auto a = run_text(R"(title: two springs in series in a plane
axes: [x, y]
parameters:
  m: {value: 2, unit: kg}
  g: {value: 9.81, unit: m/s^2}
  k_1: {value: 100, unit: N/m}
  k_2: {value: 300, unit: N/m}
  l_1: {value: 0.5, unit: m}
  l_2: {value: 0.5, unit: m}
gravity: [0, -g]
bodies:
  A: {mass: m, position: x, center_of_mass: [x, 0]}
  S: {mass: 0, position: x_S, center_of_mass: [x_S, 0]}
points:
  W: [0, 0]
connections:
  - {type: roller, body: A, at: A, normal: [0, 1]}
  - {type: spring, name: sp2, path: [W, S], k: k_2, rest_length: l_2}
  - {type: spring, name: sp1, path: [S, A], k: k_1, rest_length: l_1}
layout: {x: 1.2, x_S: 0.6}
motion:
  initial: {x: 1.2, dot(x): 0}
  until: 1
)");
  REQUIRE(a->motion);
  REQUIRE(a->motion->problem.empty());
  const EquationsOfMotion& eom = a->motion->eom;
  REQUIRE(eom.dof == 1);
  REQUIRE(eom.linear);
  const SymbolTable& t = *a->model.symbols;
  const ex k_1 = t.find("k_1")->sym, k_2 = t.find("k_2")->sym;
  CHECK(normal(eom.K(0, 0) - k_1 * k_2 / (k_1 + k_2)).is_zero());
  REQUIRE(a->motion->response);
  const double lambda = std::sqrt(37.5);
  for (const double time : {0.2, 0.5, 0.9}) {
    INFO("t = " << time);
    const double x = 1 + 0.2 * std::cos(lambda * time);
    const exmap at{{a->model.time, numeric(time)}, {a->model.motion->lambda, sqrt(numeric(75, 2))}};
    CHECK(number(a->motion->response->q, t, at) == Approx(x).epsilon(1e-12));
    const Simulation s = simulate(*a, SimulationSpec{time, {"x", "x_S"}, 2}, Location{"t.yaml", 1, 1});
    REQUIRE(s.complete);
    CHECK(*s.table.y[0].back() == Approx(x).epsilon(1e-8));
    CHECK(*s.table.y[1].back() == Approx((100 * (x - 0.5) + 150) / 400).epsilon(1e-8));
  }
}

TEST_CASE("Massless ring: its place given at the instant does not take the block's place in the motion",
          "[motion][massless]") {
  // The driven ring with y_S = -0.3 m given: at the instant T = k (y_S + H - l_0) = 40 N; in
  // time the motion is still described by the block's x (its rate is in 'initial'; before, the
  // given y_S was chosen and 'initial' was asked for dot(y_S)), with the spring's stiffness,
  // and simulate follows the ring, y_S = -0.3 - x, not its given place.
  const auto a = run_text(
      example_with(driven_ring, "find: [T, ddot(x)]", "given: {y_S: {value: -0.3, unit: m}}\nfind: [T, ddot(x)]"));
  const Derivation d = explain(*a);
  REQUIRE(d.answers.size() == 2);
  REQUIRE(d.answers[0].value);
  CHECK(d.answers[0].value->approx == Approx(40).epsilon(1e-12));
  REQUIRE(a->motion);
  REQUIRE(a->motion->problem.empty());
  REQUIRE(a->motion->eom.q.size() == 1);
  CHECK(to_text(a->motion->eom.q[0]) == "x");
  CHECK(normal(a->motion->eom.K(0, 0) - a->model.symbols->find("k")->sym).is_zero());
  const Simulation s = simulate(*a, SimulationSpec{1.0, {"x", "y_S", "T"}, 2}, Location{"t.yaml", 1, 1});
  REQUIRE(s.complete);
  const double x = driven_x(1.0);
  CHECK(*s.table.y[0].back() == Approx(x).epsilon(1e-8));
  CHECK(*s.table.y[1].back() == Approx(-0.3 - x).epsilon(1e-8));
  CHECK(*s.table.y[2].back() == Approx(200 * (0.2 - x)).epsilon(1e-8));
}
