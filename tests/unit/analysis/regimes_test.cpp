// Friction between two moving bodies (friction_between, decided at the numbers), the refusal
// of a one-body contact at a point of another moving body, the refusal of balances that
// contradict each other, and the bodies that get no balance of moments (particles). Every
// number below is derived by hand in its test.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "expr/print.hpp"
#include "motion/simulate.hpp"
#include "../../support/helpers.hpp"

using namespace tackle;

namespace {

// A (2 kg) on B (3 kg) on a smooth floor, mu_s = 0.3, mu_k = 0.25 between them; a force F
// (value `force`, in N) on `pulled` (A or B) at its center.
std::string stacked(const std::string& force, const std::string& pulled = "B", const std::string& extra = "") {
  return R"(
title: stacked blocks
axes: [x, y]
parameters:
  m_A: {value: 2, unit: kg}
  m_B: {value: 3, unit: kg}
  g: {value: 9.81, unit: m/s^2}
  F: {value: )" +
         force + R"(, unit: N, positive: false}
  mu_s: {value: 0.3}
  mu_k: {value: 0.25}
  h: {value: 0.2, unit: m}
gravity: [0, -g]
bodies:
  A: {mass: m_A, position: x_A, center_of_mass: [x_A, 3*h/2]}
  B: {mass: m_B, position: x_B, center_of_mass: [x_B, h/2]}
loads:
  - {on: )" +
         pulled + ", at: " + pulled + R"(, force: [F, 0]}
connections:
  - {type: friction_between, body: A, other: B, at: A, normal: [0, 1], tangent: [1, 0], mu_s: mu_s, mu_k: mu_k}
  - {type: roller, body: B, at: B, normal: [0, 1]}
layout: {x_A: 0, x_B: 0}
)" + extra;
}

double value(const Analysis& a, const std::string& name) {
  const SymbolInfo* s = a.model.symbols->find(name);
  REQUIRE(s);
  const auto v = a.solution.value_of(s->sym);
  REQUIRE(v);
  return test::number(*v, *a.model.symbols);
}

const RegimeChoice::Bound* bound(const RegimeChoice& c, const std::string& parameter, const std::string& op) {
  for (const auto& b : c.holds_while)
    if (to_text(b.parameter) == parameter && b.op == op && b.tightest) return &b;
  return nullptr;
}

}  // namespace

TEST_CASE("Regimes: pulled hard (20 N on B), A slips on B with kinetic friction", "[regimes]") {
  // Sticking would need F_A = m_A F/(m_A + m_B) = 8 N on A, more than mu_s m_A g = 5.886 N: A
  // slips backwards on B, and mu_k N_A = 4.905 N pushes A forwards and B back.
  // ddot(x_A) = mu_k g = 2.4525; ddot(x_B) = (20 - 4.905)/3 = 5.031667; N_A = 19.62; N_B = 49.05.
  const auto a = test::run_text(stacked("20"));
  CHECK(value(*a, "ddot(x_A)") == Approx(2.4525));
  CHECK(value(*a, "ddot(x_B)") == Approx(15.095 / 3));
  CHECK(value(*a, "N_A") == Approx(19.62));
  CHECK(value(*a, "N_B") == Approx(49.05));
  CHECK(a->model.symbols->find("F_A") == nullptr);  // (no sticking friction in the model derived)
  REQUIRE(a->regimes.size() == 1);
  const RegimeChoice& c = a->regimes[0];
  CHECK(c.connection == "sliding between at A");
  CHECK(c.first == "sticking_between");
  CHECK(c.chosen == "sliding_between");
  CHECK_FALSE(c.undecided);
  CHECK(c.failed == std::vector<std::string>{"friction can hold the bodies together (F <= mu N)"});
  // The largest load for which they move together, mu_s g (m_A + m_B) = 14.715 N, and the
  // least mu_s that would hold them at 20 N, 20/(9.81*5) = 0.407747.
  const auto* largest = bound(c, "F", "<=");
  REQUIRE(largest);
  CHECK(to_text(largest->bound) == "g*mu_s*(m_A + m_B)");
  CHECK(largest->value == "14.715 N");
  CHECK(largest->failed);
  const auto* least = bound(c, "mu_s", ">=");
  REQUIRE(least);
  CHECK(least->value == "0.407747");
  CHECK(least->coefficient);
  REQUIRE(c.friction);
  CHECK(c.friction->body == "A");
  CHECK(c.friction->value_number == "8 N");
  CHECK(c.friction->limit_number == "5.886 N");
}

TEST_CASE("Regimes: pulled gently (10 N on B), the blocks move together", "[regimes]") {
  // a = F/(m_A + m_B) = 2; F_A = m_A a = 4 N <= 5.886 N; mu_s >= 10/49.05 = 0.203874.
  const auto a = test::run_text(stacked("10"));
  CHECK(value(*a, "ddot(x_A)") == Approx(2));
  CHECK(value(*a, "ddot(x_B)") == Approx(2));
  CHECK(value(*a, "F_A") == Approx(4));
  CHECK(value(*a, "N_A") == Approx(19.62));
  REQUIRE(a->regimes.size() == 1);
  const RegimeChoice& c = a->regimes[0];
  CHECK(c.chosen == "sticking_between");
  CHECK(c.failed.empty());
  REQUIRE(bound(c, "F", "<="));
  CHECK(bound(c, "F", "<=")->value == "14.715 N");
  REQUIRE(bound(c, "F", ">="));
  CHECK(bound(c, "F", ">=")->value == "-14.715 N");  // (pulled the other way)
  // Of the two lower bounds on mu_s (0.203874 and -0.203874), the tightest.
  REQUIRE(bound(c, "mu_s", ">="));
  CHECK(bound(c, "mu_s", ">=")->value == "0.203874");
  int on_mu = 0;
  for (const auto& b : c.holds_while) on_mu += to_text(b.parameter) == "mu_s" ? 1 : 0;
  CHECK(on_mu == 2);
  REQUIRE(c.friction);
  CHECK(c.friction->value_number == "4 N");
}

TEST_CASE("Regimes: pulled hard the other way (-20 N on B), A slips forwards on B", "[regimes]") {
  // The friction sticking needs is -8 N: A slips along +x relative to B, and kinetic friction
  // pushes it along -x: ddot(x_A) = -mu_k g = -2.4525, ddot(x_B) = (-20 + 4.905)/3 = -5.031667.
  const auto a = test::run_text(stacked("-20"));
  CHECK(value(*a, "ddot(x_A)") == Approx(-2.4525));
  CHECK(value(*a, "ddot(x_B)") == Approx(-15.095 / 3));
  REQUIRE(a->regimes.size() == 1);
  CHECK(a->regimes[0].failed == std::vector<std::string>{"friction can hold the bodies together (-F <= mu N)"});
  REQUIRE(bound(a->regimes[0], "F", ">="));
  CHECK(bound(a->regimes[0], "F", ">=")->value == "-14.715 N");
}

TEST_CASE("Regimes: the top block pulled (10 N on A) slips on the bottom one", "[regimes]") {
  // Together a = 10/5 = 2, so B needs m_B a = 6 N from friction, and A gets -6 N: more than
  // 5.886 N. They move together only while F m_B/(m_A + m_B) <= mu_s m_A g, F <= 9.81 N. A slips
  // forwards: ddot(x_A) = (10 - 4.905)/2 = 2.5475, ddot(x_B) = 4.905/3 = 1.635.
  const auto a = test::run_text(stacked("10", "A"));
  CHECK(value(*a, "ddot(x_A)") == Approx(2.5475));
  CHECK(value(*a, "ddot(x_B)") == Approx(1.635));
  REQUIRE(a->regimes.size() == 1);
  CHECK(a->regimes[0].chosen == "sliding_between");
  REQUIRE(bound(a->regimes[0], "F", "<="));
  CHECK(bound(a->regimes[0], "F", "<=")->value == "9.81 N");
  REQUIRE(a->regimes[0].friction);
  CHECK(a->regimes[0].friction->value_number == "-6 N");
}

TEST_CASE("Regimes: derive says which regime and why, with the numbers", "[regimes]") {
  const auto a = test::run_text(stacked("20"));
  const std::string text = write(explain(*a), Format::text, true);
  CHECK(text.find("Sticking or slipping: sliding between at A\n") != std::string::npos);
  CHECK(text.find("    F <= g*mu_s*(m_A + m_B)  = 14.715 N    [the largest F for which they move together]\n") !=
        std::string::npos);
  CHECK(text.find("    F_A = F*m_A/(m_A + m_B)  = 8 N    [the friction on A]\n") != std::string::npos);
  CHECK(text.find("    mu_s >= F/(g*m_A + g*m_B)  = 0.407747    [the least mu_s that would hold them together]\n") !=
        std::string::npos);
  CHECK(text.find("At the given numbers they do not (friction can hold the bodies together (F <= mu N) fails): the "
                  "bodies slip on "
                  "each other, and the contact is derived here sliding (sliding_between), with kinetic friction "
                  "against the slip.") != std::string::npos);
}

TEST_CASE("Regimes: a load growing in time is derived sticking, and simulate stops where A starts to slip",
          "[regimes]") {
  // F = c t with c = 10 N/s: sticking holds while c t <= 14.715 N, until t = 1.4715 s; the
  // conditions have no number at the given numbers (they depend on t).
  std::string text = stacked("0");
  text.replace(text.find("  F: {value: 0, unit: N, positive: false}"),
               std::string("  F: {value: 0, unit: N, positive: false}").size(), "  c: {value: 10, unit: N/s}");
  text.replace(text.find("force: [F, 0]"), std::string("force: [F, 0]").size(), "force: [c*t, 0]");
  text += "motion:\n  initial: {x_A: 0, dot(x_A): 0, x_B: 0}\n  until: 3\n";
  const auto a = test::run_text(text);
  REQUIRE(a->regimes.size() == 1);
  CHECK(a->regimes[0].chosen == "sticking_between");
  CHECK(a->regimes[0].undecided);
  const Simulation s = simulate(*a, SimulationSpec{}, Location{});
  CHECK_FALSE(s.complete);
  CHECK(s.reached == Approx(1.4715).epsilon(1e-6));
  REQUIRE_FALSE(s.events.empty());
  CHECK(s.events.back().what == "sticking between at A: the bodies slip on each other");
}

TEST_CASE("Regimes: slipping from relative rest, simulate runs on (the slip starts, it is no event)", "[regimes]") {
  // 20 N on B, both at rest: the slip speed dot(x_B) - dot(x_A) grows at 5.031667 - 2.4525 =
  // 2.579167 m/s^2 from 0; after 1 s, x_A = 2.4525/2 = 1.22625 m and x_B = 5.031667/2 = 2.515833 m.
  const auto a = test::run_text(
      stacked("20", "B", "motion:\n  initial: {x_A: 0, dot(x_A): 0, x_B: 0, dot(x_B): 0}\n  until: 1\n"));
  const Simulation s = simulate(*a, SimulationSpec{}, Location{});
  CHECK(s.complete);
  CHECK(s.events.empty());
  REQUIRE(s.table.names.size() == 2);
  CHECK(*s.table.y[0].back() == Approx(1.22625).epsilon(1e-8));
  CHECK(*s.table.y[1].back() == Approx(15.095 / 6).epsilon(1e-8));
}

TEST_CASE("Refused: a one-body contact at a point of another moving body names the two-body rule",
          "[regimes][errors]") {
  std::string text = stacked("20");
  text.replace(text.find("  - {type: friction_between"),
               text.find("  - {type: roller") - text.find("  - {type: friction_between"),
               "  - {type: sliding, body: A, at: P, normal: [0, 1], sliding: [-1, 0], mu: mu_k}\n");
  text.replace(text.find("loads:"), 0, "points:\n  P: {on: B, offset: [0, h/2]}\n");
  CHECK(test::errors_of(text) ==
        std::vector<std::string>{
            "t.yaml:21:34: 'at' of a 'sliding' connection is point 'P' of body 'B', which moves: this connection "
            "holds 'A' against the ground, and the force on 'B' would be missing (expected a fixed point or a "
            "point of 'A'; for two bodies: {type: sliding_between, body: A, other: B, ...})"});
}

TEST_CASE("Refused: a block whose moments cannot cancel (a push above its center, no angle)", "[regimes][errors]") {
  // Pushed at P, h above its center, on a roller under its center: the push's moment F h has
  // nothing to balance it and the block has no angle to turn with.
  const auto errors = test::errors_of(R"(
title: pushed high
axes: [x, y]
parameters: {m: {value: 1, unit: kg}, g: {value: 9.81, unit: m/s^2}, F: {value: 2, unit: N}, h: {value: 0.5, unit: m}}
gravity: [0, -g]
bodies:
  A: {mass: m, position: x, center_of_mass: [x, 0]}
points:
  P: {on: A, offset: [0, h]}
loads:
  - {on: A, at: P, force: [F, 0]}
connections:
  - {type: roller, body: A, at: A, normal: [0, 1]}
)");
  CHECK(
      errors ==
      std::vector<std::string>{
          "t.yaml:7:3: the balances cannot all hold: AMB A about its center of mass (z) reads 0 = a moment that is not "
          "zero (expected body 'A' does not turn (it has no angle), so the moments on it must cancel: a second "
          "contact, "
          "its forces through its center of mass, or an angle and a shape or inertia to turn with)"});
}

TEST_CASE(
    "Particles: no balance of moments for a block without shape, size or angle, one for a bob, a pinned block, a "
    "suitcase",
    "[regimes]") {
  auto ambs = [](const Analysis& a) {
    std::vector<std::string> out;
    for (const auto& e : a.system.equations)
      if (e.kind == Equation::Kind::amb) out.push_back(e.label);
    return out;
  };
  // Stacked blocks, the contact at A's center: both are particles.
  CHECK(ambs(*test::run_text(stacked("10"))).empty());
  // A bob on a light rod turns (its angle): its balance of moments gives ddot(theta). (The
  // cart is drawn with a shape, which is drawing only, and the pin P is at its center: a
  // particle, with no balance of moments of its own, which read 0 = 0.)
  CHECK(ambs(*analyze_file(TACKLE_SOURCE_DIR "/examples/rotation-pendulum-on-a-cart.yaml", test::rules())) ==
        std::vector<std::string>{"AMB bob about its center of mass (z)"});
  // A block pinned at a point of the block in front, a distance behind that one's center:
  // the pin's force has a moment about it (H_y (b + x_B - x_A) = 0).
  const auto pinned = ambs(*analyze_file(TACKLE_SOURCE_DIR "/examples/two-blocks-joined-by-a-pin.yaml", test::rules()));
  CHECK(std::find(pinned.begin(), pinned.end(), "AMB B about its center of mass (z)") != pinned.end());
}
