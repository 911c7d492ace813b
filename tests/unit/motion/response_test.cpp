// The closed-form response of one degree of freedom, against a hand derivation.
#include <catch2/catch.hpp>

#include "expr/parse.hpp"
#include "motion/simulate.hpp"

#include <cmath>
#include "../../support/helpers.hpp"

using namespace tackle;
using namespace tackle::test;
using namespace GiNaC;

TEST_CASE("Response: a constant force given by a defined parameter is checked in the equation of motion", "[motion]") {
  // m x'' = F_0 - k x with F_0 = m g_0 defined: from rest at x = 0, x = F_0/k (1 - cos(lambda t)),
  // lambda = sqrt(k/m). The check puts the response back with F_0 replaced by its definition:
  // a residual left with F_0 in it cannot be evaluated, and then nothing would be checked.
  const auto a = run_text(R"(title: pushed block on a spring
axes: [x]
parameters:
  m: {value: 2, unit: kg}
  k: {value: 200, unit: N/m}
  g_0: {value: 5, unit: m/s^2}
  F_0: {define: m*g_0}
  L: {value: 0.5, unit: m}
bodies:
  block: {mass: m, position: x}
points:
  W: -L
connections:
  - {type: spring, name: sp, path: [W, block], k: k, rest_length: L}
loads:
  - {on: block, force: F_0}
layout: {x: 0}
given: [x]
find: [ddot(x)]
motion:
  initial: {x: 0, dot(x): 0}
)");
  REQUIRE(a->motion);
  REQUIRE(a->motion->response);
  const Response& r = *a->motion->response;
  CHECK(r.verified);
  const SymbolTable& table = *a->model.symbols;
  const auto want = parse_expression("F_0/k*(1 - cos(sqrt(k/m)*t))", table);
  REQUIRE(want.value);
  exmap defs = table.definitions();
  for (const auto& [sym, def] : a->motion->definitions) defs[sym] = def;
  ex difference = r.q - *want.value;
  for (int depth = 0; depth < 4; ++depth) difference = difference.subs(defs);
  CHECK(normal(difference).is_zero());
}

namespace {

// A block on a rough incline (theta = 30 deg, mu = 0.2) held by a spring (k = 200 N/m, rest
// l_0 = 0.5 m) from Q up the incline at D = 1.5 m; it slides down, so friction acts up.
std::string rough_incline(const std::string& initial) {
  return R"y(title: block on a rough incline and a spring
axes: [x, y]
parameters:
  m: {value: 2, unit: kg}
  g: {value: 9.81, unit: m/s^2}
  theta: {value: 30, unit: deg}
  mu: 0.2
  k: {value: 200, unit: N/m}
  l_0: {value: 0.5, unit: m}
  D: {value: 1.5, unit: m}
gravity: [0, -g]
bodies:
  block: {mass: m, position: s, center_of_mass: ["s*cos(theta)", "s*sin(theta)"]}
points:
  Q: ["D*cos(theta)", "D*sin(theta)"]
connections:
  - {type: sliding, body: block, at: block, normal: ["-sin(theta)", "cos(theta)"], sliding: ["-cos(theta)", "-sin(theta)"], mu: mu}
  - {type: spring, name: sp, path: [block, Q], k: k, rest_length: l_0}
layout: {s: 0.8}
motion:
  initial: )y" +
         initial + "\n  until: 1\n";
}

}  // namespace

TEST_CASE("Response: sliding friction - the closed form holds until the block stops (issue 30)", "[motion][trust]") {
  // By hand: m s'' = k (D - s - l_0) - m g sin(theta) + mu m g cos(theta): an oscillation about
  // s_eq with lambda = sqrt(k/m) = 10 rad/s. From rest it stops after half a period, pi/lambda,
  // where friction would reverse.
  const auto a = run_text(rough_incline("{s: 1.2, dot(s): 0}"));
  REQUIRE(a->motion);
  REQUIRE(a->motion->response);
  const Motion& mo = *a->motion;
  REQUIRE(mo.direction_assumed_by == std::vector<std::string>{"sliding at block"});
  REQUIRE(mo.direction_until);
  CHECK((*mo.direction_until - Pi / a->model.motion->lambda).is_zero());
  REQUIRE(mo.direction_until_s);
  CHECK(*mo.direction_until_s == Approx(M_PI / 10).epsilon(1e-12));
  // Moving down at 0.5 m/s: s = s_eq + A cos(lambda t) + B sin(lambda t), A = s_0 - s_eq,
  // B = v_0/lambda; the rate lambda (B cos - A sin) first vanishes where tan(lambda t) = B/A.
  const auto b = run_text(rough_incline("{s: 1.2, dot(s): -0.5}"));
  REQUIRE(b->motion);
  const double s_eq = (1.5 * 200 + 2 * 9.81 * 0.2 * std::cos(M_PI / 6) - 2 * 9.81 * 0.5 - 200 * 0.5) / 200;
  const double A = 1.2 - s_eq, B = -0.5 / 10, phase = std::atan(B / A);
  const double t_1 = (phase > 0 ? phase : phase + M_PI) / 10;
  CHECK(!b->motion->direction_until);
  REQUIRE(b->motion->direction_until_s);
  CHECK(*b->motion->direction_until_s == Approx(t_1).epsilon(1e-9));
  // simulate stops at the same instant.
  const Simulation s = simulate(*a, SimulationSpec{}, Location{"t.yaml", 1, 1});
  REQUIRE(!s.events.empty());
  CHECK(s.events.back().t == Approx(M_PI / 10).epsilon(1e-8));
}

TEST_CASE("Response: sliding friction - a start against the assumed sliding direction is refused (issue 30)",
          "[motion][trust]") {
  // By hand at s = 0.8 m: the spring is 0.7 m long, stretched 0.2 m, so it pulls up the
  // incline with 40 N against m g sin(theta) = 9.81 N down: from rest the block starts up the
  // incline, but the rule's friction (up the incline, for sliding down) would push it along.
  // Moving up at 1 m/s, the same. At s = 1.2 m from rest (compressed spring) it starts down.
  const std::string up =
      "from rest, the forces start body 'block' against the sliding direction that sliding at block "
      "assumes (its friction would push it along, not hold it back)";
  const auto a = run_text(rough_incline("{s: 0.8, dot(s): 0}"));
  REQUIRE(a->motion);
  CHECK(a->motion->direction_against == up);
  const Simulation s = simulate(*a, SimulationSpec{}, Location{"t.yaml", 1, 1});
  REQUIRE(s.events.size() == 1);
  CHECK(s.events[0].t == 0);
  CHECK(s.events[0].what == up);
  CHECK(!s.complete);
  const auto b = run_text(rough_incline("{s: 0.8, dot(s): 1}"));
  REQUIRE(b->motion);
  CHECK(b->motion->direction_against ==
        "at t = 0 body 'block' moves against the sliding direction that sliding at block "
        "assumes (its friction would push it along, not hold it back)");
  for (const char* agrees : {"{s: 1.2, dot(s): 0}", "{s: 0.8, dot(s): -1}"}) {
    const auto c = run_text(rough_incline(agrees));
    REQUIRE(c->motion);
    CHECK(c->motion->direction_against.empty());
  }
}
