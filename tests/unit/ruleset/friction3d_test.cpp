// Friction in 3-D: a contact that does not slip carries friction anywhere in its tangent plane
// (two unknown components, along the tangent and along normal x tangent), and holds while
// their resultant is at most mu N. Numbers derived by hand in each case.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>

#include "expr/print.hpp"
#include "../../support/helpers.hpp"

using namespace tackle;
using namespace GiNaC;

namespace {

// A block on a horizontal turntable at (r, 0, 0), z up: omega^2 r towards the axis, alpha r
// along its path.
std::string turntable(const std::string& alpha, const std::string& mu) {
  return R"(title: turntable
axes: [x, y, z]
parameters:
  m: {value: 2, unit: kg}
  r: {value: 0.5, unit: m}
  omega: {value: 2, unit: rad/s}
  alpha: {value: )" +
         alpha + R"(, unit: rad/s^2}
  mu: {value: )" +
         mu + R"(, positive: true}
  g: {value: 9.81, unit: m/s^2}
gravity: [0, 0, -g]
bodies:
  block: {mass: m, acceleration: ["-omega^2*r", "alpha*r", 0], center_of_mass: [r, 0, 0]}
points:
  C: {on: block}
connections:
  - {type: sticking, body: block, at: C, normal: [0, 0, 1], tangent: [1, 0, 0], mu: mu}
find: [N_C, F_C1, F_C2]
)";
}

std::map<std::string, std::string> closed_forms(const Derivation& d) {
  std::map<std::string, std::string> out;
  for (const auto& a : d.answers) out[a.name] = to_text(*a.closed_form);
  return out;
}

std::map<std::string, double> values(const Derivation& d) {
  std::map<std::string, double> out;
  for (const auto& a : d.answers) out[a.name] = a.value->approx;
  return out;
}

// The friction condition (the one with the root) and its form solved for mu.
const ConditionReport& friction_condition(const Derivation& d) {
  const auto it = std::find_if(d.conditions.begin(), d.conditions.end(), [](const ConditionReport& c) {
    return c.meaning == "friction can hold (sqrt(F_1^2 + F_2^2) <= mu N)";
  });
  REQUIRE(it != d.conditions.end());
  return *it;
}

const SolvedFor& solved_for(const ConditionReport& c, const std::string& parameter) {
  const auto it = std::find_if(c.solved.begin(), c.solved.end(),
                               [&](const SolvedFor& s) { return to_text(s.parameter) == parameter; });
  REQUIRE(it != c.solved.end());
  return *it;
}

}  // namespace

TEST_CASE("Friction 3-D: a block on a turning platform needs mu >= omega^2 r / g", "[rules][friction3d]") {
  // Steady turning (alpha = 0): friction towards the axis, F_C1 = -m omega^2 r = -4 N, none
  // along the path; N_C = m g = 19.62 N; m omega^2 r <= mu m g: mu >= omega^2 r/g = 2/9.81.
  std::string steady = turntable("0", "0.4");
  steady.erase(steady.find("  alpha: {value: 0, unit: rad/s^2}\n"),
               std::string("  alpha: {value: 0, unit: rad/s^2}\n").size());
  steady.replace(steady.find("\"alpha*r\""), std::string("\"alpha*r\"").size(), "0");
  const Derivation d = explain(*test::run_text(steady));
  CHECK(closed_forms(d) == std::map<std::string, std::string>{{"N_C", "g*m"}, {"F_C1", "-m*omega^2*r"}, {"F_C2", "0"}});
  const auto v = values(d);
  CHECK(v.at("N_C") == Approx(19.62));
  CHECK(v.at("F_C1") == Approx(-4.0));
  CHECK(v.at("F_C2") == Approx(0.0).margin(1e-12));
  const ConditionReport& c = friction_condition(d);
  CHECK(c.holds == std::optional<bool>(true));
  const SolvedFor& mu = solved_for(c, "mu");
  CHECK(mu.op == ">=");
  CHECK(to_text(mu.bound) == "omega^2*r/g");
  REQUIRE(mu.number);
  CHECK(mu.number->value.approx == Approx(2.0 / 9.81));
}

TEST_CASE("Friction 3-D: a turntable that speeds up needs friction in the whole tangent plane", "[rules][friction3d]") {
  // alpha = 3 rad/s^2: F_C1 = -4 N towards the axis, F_C2 = m alpha r = 3 N along the path,
  // |F| = 5 N, N_C = 19.62 N: mu >= r sqrt(omega^4 + alpha^2)/g = 0.5*5/9.81 = 0.254842.
  SECTION("mu = 0.4 holds it") {
    const Derivation d = explain(*test::run_text(turntable("3", "0.4")));
    CHECK(closed_forms(d) ==
          std::map<std::string, std::string>{{"N_C", "g*m"}, {"F_C1", "-m*omega^2*r"}, {"F_C2", "alpha*m*r"}});
    CHECK(values(d).at("F_C2") == Approx(3.0));
    const ConditionReport& c = friction_condition(d);
    CHECK(to_text(c.simplified) == "m*r*sqrt(alpha^2 + omega^4) - g*m*mu");
    CHECK(c.holds == std::optional<bool>(true));
    const SolvedFor& mu = solved_for(c, "mu");
    CHECK(to_text(mu.bound) == "r*sqrt(alpha^2 + omega^4)/g");
    REQUIRE(mu.number);
    CHECK(mu.number->value.approx == Approx(2.5 / 9.81));
  }
  SECTION("mu = 0.2 lets it slip") {
    const Derivation d = explain(*test::run_text(turntable("3", "0.2")));
    const ConditionReport& c = friction_condition(d);
    CHECK(c.holds == std::optional<bool>(false));
    CHECK(c.otherwise == "the contact slips");
  }
  SECTION("with one tangent the block cannot be held: the y balance reads 0 = m alpha r") {
    std::string one = turntable("3", "0.4");
    // The 2-D rule's friction along one line, written out as a force of unknown size.
    const auto at = one.find("  - {type: sticking");
    one = one.substr(0, at) +
          "  - {type: roller, body: block, at: C, normal: [0, 0, 1]}\n"
          "  - {type: collar, body: block, at: C, across: [1, 0, 0], across_too: [0, 0, 1], force: F_x, force_too: Q}\n"
          "find: [N_C, F_x]\n";
    const auto errors = test::errors_of(one);
    REQUIRE(errors.size() == 1);
    CHECK(errors[0].find("the balances cannot all hold") != std::string::npos);
  }
}

TEST_CASE("Friction 3-D: a block on a rough incline pushed sideways, the incline written in parameters",
          "[rules][friction3d]") {
  // A 3-4-5 incline: normal (-a, 0, b), up the slope (b, 0, a), a = 3, b = 4; normal x tangent
  // = (0, a^2 + b^2, 0), along +y (a and b positive). Weight m g = 20 N, a push P = 9 N along +y. By hand:
  // N_C = m g b/5 = 16 N, F_C1 = m g a/5 = 12 N up the slope, F_C2 = -P = -9 N; |F| = 15 N:
  // mu >= 15/16 = 0.9375. (a inside sqrt(a^2 + b^2) once was 'internal error: power::degree()'.)
  const std::string incline = R"(title: incline
axes: [x, y, z]
parameters:
  m: {value: 2, unit: kg}
  g: {value: 10, unit: m/s^2}
  P: {value: 9, unit: N}
  a: {value: 3, positive: true}
  b: {value: 4, positive: true}
  mu: {value: 1, positive: true}
gravity: [0, 0, -g]
bodies:
  block: {mass: m, center_of_mass: [0, 0, 0]}
points:
  C: {on: block}
loads:
  - {on: block, at: C, force: [0, P, 0]}
connections:
  - {type: sticking, body: block, at: C, normal: ["-a", 0, b], tangent: [b, 0, a], mu: mu}
find: [N_C, F_C1, F_C2]
)";
  const Derivation d = explain(*test::run_text(incline));
  const auto forms = closed_forms(d);
  CHECK(forms.at("N_C") == "b*g*m/sqrt(a^2 + b^2)");
  CHECK(forms.at("F_C1") == "a*g*m/sqrt(a^2 + b^2)");
  const auto v = values(d);
  CHECK(v.at("N_C") == Approx(16.0));
  CHECK(v.at("F_C1") == Approx(12.0));
  CHECK(v.at("F_C2") == Approx(-9.0));
  const ConditionReport& c = friction_condition(d);
  CHECK(c.holds == std::optional<bool>(true));
  const SolvedFor& mu = solved_for(c, "mu");
  // mu >= sqrt(F_C1^2 + F_C2^2)/N_C = sqrt(P^2 (a^2 + b^2) + a^2 g^2 m^2)/(b g m) = 75/80.
  CHECK(mu.op == ">=");
  CHECK(to_text(mu.bound) == "sqrt(P^2*a^2 + P^2*b^2 + a^2*g^2*m^2)/(b*g*m)");
  REQUIRE(mu.number);
  CHECK(mu.number->value.approx == Approx(0.9375));
  // Not solved for a or b: they are inside the roots.
  for (const auto& s : c.solved) CHECK((to_text(s.parameter) != "a" && to_text(s.parameter) != "b"));
}

TEST_CASE("Friction 3-D: a normal or tangent written in parameters is a right answer or a located error",
          "[rules][friction3d]") {
  const std::string head = R"(title: t
axes: [x, y, z]
parameters:
  m: {value: 2, unit: kg}
  a: {value: 1}
  h: {value: 0}
  mu: {value: 0.4, positive: true}
  g: {value: 9.81, unit: m/s^2}
gravity: [0, 0, -g]
bodies:
  block: {mass: m, center_of_mass: [0, 0, 0]}
points:
  C: {on: block}
connections:
)";
  SECTION("a tangent along the normal") {
    CHECK(test::errors_of(
              head + "  - {type: sticking, body: block, at: C, normal: [0, 0, 1], tangent: [0, 0, a], mu: mu}\n") ==
          std::vector<std::string>{
              "t.yaml:15:71: 'tangent' of a 'sticking' connection, [0, 0, a], is not at right angles to its "
              "'normal', [0, 0, 1]: their dot product is a = 1 at the given numbers (expected a direction at "
              "right angles to 'normal')"});
  }
  SECTION("a tangent not at right angles to the normal") {
    CHECK(test::errors_of(
              head + "  - {type: sticking, body: block, at: C, normal: [0, 0, 1], tangent: [1, 0, 1], mu: mu}\n") ==
          std::vector<std::string>{
              "t.yaml:15:71: 'tangent' of a 'sticking' connection, [1, 0, 1], is not at right angles to its "
              "'normal', [0, 0, 1]: their dot product is 1 (expected a direction at right angles to 'normal')"});
  }
  SECTION("a normal that is zero at the given numbers") {
    CHECK(test::errors_of(
              head + "  - {type: sticking, body: block, at: C, normal: [0, 0, h], tangent: [1, 0, 0], mu: mu}\n") ==
          std::vector<std::string>{
              "t.yaml:15:51: 'normal' of a 'sticking' connection is the zero vector at the given numbers "
              "(expected a direction)"});
  }
  SECTION("a normal in a parameter: the answer") {
    // normal (0, 0, a), a = 1: N_C = m g a/sqrt(a^2) (a's sign is not known), 19.62 N.
    const Derivation d =
        explain(*test::run_text(
            head + "  - {type: sticking, body: block, at: C, normal: [0, 0, a], tangent: [1, 0, 0], mu: mu}\n"
                   "find: [N_C]\n"));
    REQUIRE(d.answers.size() == 1);
    CHECK(d.answers[0].value->approx == Approx(19.62));
  }
}

TEST_CASE("Friction: a normal with a parameter inside a root is answered, never 'internal error: power::degree()'",
          "[rules][friction3d]") {
  // A contact whose normal is (sqrt(1 - a^2), a): with a = 1/2 the incline's normal is at 30
  // deg from the x axis. Weight m g = 20 N along -y. By hand: N_C = m g a = 10 N, the
  // friction along (a, -sqrt(1 - a^2)) is -m g sqrt(1 - a^2) = -17.3205 N. Solving the
  // friction condition for a once asked for the degree of sqrt(1 - a^2) in a (exit 3).
  std::string text = R"y(title: root
axes: [x, y]
parameters:
  m: {value: 2, unit: kg}
  g: {value: 10, unit: m/s^2}
  a: {value: 0.5}
  mu: {value: 1, positive: true}
gravity: [0, -g]
bodies:
  block: {mass: m, center_of_mass: [0, 0]}
points:
  C: {on: block}
connections:
  - {type: sticking, body: block, at: C, normal: ["sqrt(1-a^2)", a], tangent: [a, "-sqrt(1-a^2)"], mu: mu}
)y";
  SECTION("2-D") {
    const Derivation d = explain(*test::run_text(text));
    CHECK(closed_forms(d) == std::map<std::string, std::string>{{"N_C", "a*g*m"}, {"F_C", "-g*m*sqrt(1 - a^2)"}});
    CHECK(values(d).at("F_C") == Approx(-10.0 * std::sqrt(3.0)));
    // -F <= mu N: 17.3205 <= 10 fails: it slips.
    REQUIRE(d.conditions.size() == 3);
    CHECK(d.conditions[2].holds == std::optional<bool>(false));
  }
  SECTION("3-D") {
    for (const auto& [from, to] : {std::pair<std::string, std::string>{"axes: [x, y]", "axes: [x, y, z]"},
                                   {"gravity: [0, -g]", "gravity: [0, -g, 0]"},
                                   {"center_of_mass: [0, 0]", "center_of_mass: [0, 0, 0]"},
                                   {"a], tangent", "a, 0], tangent"},
                                   {"\"-sqrt(1-a^2)\"]", "\"-sqrt(1-a^2)\", 0]"}})
      text.replace(text.find(from), from.size(), to);
    const Derivation d = explain(*test::run_text(text));
    CHECK(closed_forms(d) ==
          std::map<std::string, std::string>{{"N_C", "a*g*m"}, {"F_C1", "-g*m*sqrt(1 - a^2)"}, {"F_C2", "0"}});
    const ConditionReport& c = friction_condition(d);
    CHECK(to_text(c.simplified) == "g*m*(sqrt(1 - a^2) - a*mu)");
    CHECK(c.holds == std::optional<bool>(false));
  }
}
