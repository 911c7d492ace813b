// Starting values of a motion (issue 30, item 4): 'initial' gives the motion's coordinates
// and rates; a dependent coordinate's starting value follows from the constraints where
// they fix it, is asked for only where they fix it up to a constant (and then by its own
// name), and a dependent rate that is given must be the one the constraints give.
// Expected values by hand.
#include <catch2/catch.hpp>

#include "report/sweep.hpp"
#include "numeric/evaluate.hpp"
#include "../../support/helpers.hpp"

using namespace tackle;
using namespace tackle::test;
using namespace GiNaC;

namespace {

// An Atwood machine (y up) whose block B also hangs on a spring (k, rest l) from the floor
// point G at y = -d_G. The pulley C is fixed.
const std::string atwood_on_a_spring = R"(title: Atwood machine with a spring under B
axes: [y]
parameters:
  m_A: {value: 3, unit: kg}
  m_B: {value: 5, unit: kg}
  g: {value: 9.81, unit: m/s^2}
  k: {value: 100, unit: N/m}
  l: {value: 0.5, unit: m}
  d_G: {value: 6, unit: m}
gravity: -g
bodies:
  A: {mass: m_A, position: y_A}
  B: {mass: m_B, position: y_B}
  C: {mass: 0, position: y_C}
points:
  G: -d_G
strings:
  - {name: s, path: [A, C, B], tension: T}
connections:
  - {type: fixed, body: C}
  - {type: pulley, at: C}
  - {type: spring, name: sp, path: [B, G], k: k, rest_length: l}
layout: {y_A: -2, y_B: -3, y_C: 0}
find: [T]
motion:
)";

}  // namespace

TEST_CASE("Starting values: the string's length needs B's start, not the fixed pulley's height",
          "[motion][errors][trust]") {
  // The string keeps 2 y_C - y_A - y_B; C is fixed, so y_B = y_A(0) + y_B(0) - y_A: y_C(0)
  // cancels and y_B(0) is what is missing.
  CHECK(errors_of(atwood_on_a_spring + "  initial: {y_A: -2, dot(y_A): 0}\n") ==
        std::vector<std::string>{
            "t.yaml:26:3: the motion needs the initial value of y_B (the constraints fix it only up to a "
            "constant; expected it in 'initial')"});
}

TEST_CASE("Starting values: given B's start, the motion follows the spring through the string", "[motion][trust]") {
  // By hand: A: T - m_A g = m_A y_A''; B: T - m_B g - k (y_B + d_G - l) = m_B y_B''; the
  // string gives y_B = S - y_A with S = y_A(0) + y_B(0) = -5 m, y_B'' = -y_A''. So
  // (m_A + m_B) y_A'' + k y_A = (m_B - m_A) g + k (S + d_G - l): lambda = sqrt(k/(m_A + m_B)),
  // equilibrium y_eq = (m_B - m_A) g/k + S + d_G - l = 0.1962 + 0.5 = 0.6962 m, and from rest
  // y_A(t) = y_eq + (-2 - y_eq) cos(lambda t).
  const auto a = run_text(atwood_on_a_spring + "  initial: {y_A: -2, dot(y_A): 0, y_B: -3}\n");
  REQUIRE(a->motion);
  REQUIRE(a->motion->response);
  const SymbolTable& t = *a->model.symbols;
  const double lambda = std::sqrt(100.0 / 8), y_eq = 2 * 9.81 / 100 + 0.5;
  for (const double time : {0.0, 0.3, 1.1}) {
    const exmap at{{a->model.time, numeric(time)}, {a->model.motion->lambda, numeric(lambda)}};
    CHECK(number(a->motion->response->q, t, at) == Approx(y_eq + (-2 - y_eq) * std::cos(lambda * time)).epsilon(1e-9));
  }
}

TEST_CASE("Starting values: a dependent rate that is given must agree with the constraints",
          "[motion][errors][trust]") {
  // dot(y_B) = -dot(y_A) = 0 at t = 0: 0 is accepted, 1 is refused where it is written.
  CHECK(errors_of(atwood_on_a_spring + "  initial: {y_A: -2, dot(y_A): 0, y_B: -3, dot(y_B): 0}\n").empty());
  CHECK(errors_of(atwood_on_a_spring + "  initial: {y_A: -2, dot(y_A): 0.5, y_B: -3, dot(y_B): 1}\n") ==
        std::vector<std::string>{
            "t.yaml:26:56: initial value of 'dot(y_B)' is 1, but the constraints give dot(y_B) = "
            "-dot(y_A) = -1/2 at t = 0 (expected that value, or none: it follows from the motion's rates)"});
}

TEST_CASE("Starting values: a strand whose length needs a start 'initial' does not give is said not to be followed",
          "[motion][trust]") {
  // y_C(0) cancels from the motion, but the strands A-C and C-B are y_C - y_A and y_C - y_B:
  // without it, the moment A runs into the pulley cannot be found, and tackle says so.
  const auto a = run_text(atwood_on_a_spring + "  initial: {y_A: -2, dot(y_A): 0, y_B: -3}\n");
  REQUIRE(a->motion);
  REQUIRE(a->motion->strands_in_state.size() == 1);  // the spring's, y_B + d_G = S + d_G - y_A
  CHECK(a->motion->strands_in_state[0].first == "strand B-G of spring sp");
  REQUIRE(a->motion->not_followed.size() == 2);
  CHECK(a->motion->not_followed[0].first == "strand A-C of string s");
  CHECK(a->motion->not_followed[0].second ==
        "its length depends on y_C, whose value at t = 0 'initial' does not give (expected it there)");
  CHECK(a->motion->not_followed[1].first == "strand C-B of string s");
}

TEST_CASE("Starting values: with the pulley's height given, A running into the pulley ends the motion",
          "[motion][trust]") {
  // From the response by hand (above), y_A(t) = y_eq + (-2 - y_eq) cos(lambda t) reaches the
  // pulley at y_C = 0 when cos(lambda t) = y_eq/(y_eq + 2); the string is still taut there
  // (T = m_A (g + y_A'') < 0 only above y_A = y_eq + g/lambda^2 = 1.48 m), and the spring's
  // length, y_B + d_G = 1 - y_A, is still 1 m.
  const auto a = run_text(atwood_on_a_spring + "  initial: {y_A: -2, dot(y_A): 0, y_B: -3, y_C: 0}\n  until: 2\n");
  REQUIRE(a->motion);
  CHECK(a->motion->not_followed.empty());
  CHECK(a->motion->strands_in_state.size() == 3);
  const Simulation s = simulate(*a, SimulationSpec{}, Location{"t.yaml", 1, 1});
  REQUIRE(s.events.size() == 1);
  CHECK(s.events[0].what == "strand A-C of string s: its length reaches zero (a body reaches the point at its end)");
  const double lambda = std::sqrt(100.0 / 8), y_eq = 2 * 9.81 / 100 + 0.5;
  CHECK(s.events[0].t == Approx(std::acos(y_eq / (y_eq + 2)) / lambda).epsilon(1e-7));
}

TEST_CASE("Units: a plain number on a spring's path is read in metres, not refused as a pure number",
          "[motion][units]") {
  // G at -6 (a number, SI) instead of -d_G: the spring's force k (y_B + 6 - l) is a force.
  // (The balance's terms used to be checked after expansion, where 6 k is a stiffness.)
  std::string text = atwood_on_a_spring + "  initial: {y_A: -2, dot(y_A): 0, y_B: -3}\n";
  text.replace(text.find("  G: -d_G"), 9, "  G: -6");
  const auto a = run_text(text);
  REQUIRE(a->motion);
  REQUIRE(a->motion->response);
  const double lambda = std::sqrt(100.0 / 8), y_eq = 2 * 9.81 / 100 + 0.5;
  const exmap at{{a->model.time, numeric(0.7)}, {a->model.motion->lambda, numeric(lambda)}};
  CHECK(number(a->motion->response->q, *a->model.symbols, at) ==
        Approx(y_eq + (-2 - y_eq) * std::cos(lambda * 0.7)).epsilon(1e-9));
}

TEST_CASE("Starting values: the plain Atwood machine follows its strands when 'initial' places them",
          "[motion][trust]") {
  // Nothing asked for needs y_B or y_C, but the strands do: from rest at y_A = -2 with
  // ddot(y_A) = (m_B - m_A) g/(m_A + m_B) = 2.4525 m/s^2, A reaches the pulley (y_C = 0) at
  // t = sqrt(2 * 2/2.4525) = 1.27710 s.
  const std::string atwood = read_example("atwood-machine.yaml");
  const auto a = run_text(atwood + "motion:\n  initial: {y_A: -2, dot(y_A): 0, y_B: -3, y_C: 0}\n  until: 2\n");
  REQUIRE(a->motion);
  CHECK(a->motion->not_followed.empty());
  const Simulation s = simulate(*a, SimulationSpec{}, Location{"t.yaml", 1, 1});
  REQUIRE(s.events.size() == 1);
  CHECK(s.events[0].t == Approx(std::sqrt(4 / 2.4525)).epsilon(1e-7));
  // Without the starts, the run does not claim that the model holds: it names what it does not watch.
  const auto b = run_text(atwood + "motion:\n  initial: {y_A: -2, dot(y_A): 0}\n  until: 2\n");
  const std::string text = simulation_text(simulate(*b, SimulationSpec{}, Location{"t.yaml", 1, 1}));
  CHECK(text.find("the model holds throughout") == std::string::npos);
  CHECK(text.find("what it follows holds throughout.\nNot followed: strand A-C of string s (its length depends on y_C, "
                  "whose value at t = 0 'initial' does not give (expected it there)).\n") != std::string::npos);
}
