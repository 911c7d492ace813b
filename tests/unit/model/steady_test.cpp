// A steady motion whose rate is the unknown (`steady:`): the conical pendulum of
// examples/rotation-conical-pendulum.yaml, whose hand derivation is in its notes.
#include <catch2/catch.hpp>

#include "expr/print.hpp"
#include "../../support/helpers.hpp"

using namespace tackle;
using Messages = std::vector<std::string>;

namespace {

std::string pendulum_with(const std::string& from, const std::string& to) {
  return test::example_with("rotation-conical-pendulum.yaml", from, to);
}

const Answer& answer_named(const Derivation& d, const std::string& name) {
  const auto a = std::find_if(d.answers.begin(), d.answers.end(), [&](const Answer& x) { return x.name == name; });
  REQUIRE(a != d.answers.end());
  return *a;
}

}  // namespace

TEST_CASE("Steady: the rate's square is an unknown, the rate reported in the unit asked", "[steady]") {
  // By hand: omega^2 = g/(L cos(theta)) = 9.43968 rad^2/s^2, omega = 3.07241 rad/s = 3.07241 *
  // 60/(2 pi) rpm = 29.3393 rpm; the period does not depend on the unit, 2.04504 s.
  const auto a =
      test::run_text(pendulum_with("steady: {rate: omega, period: tau}", "steady: {rate: omega, unit: rpm}"));
  const Derivation d = explain(*a);
  CHECK(to_text(a->model.steady->squared) == "omega^2");
  CHECK(std::find(a->system.unknowns.begin(), a->system.unknowns.end(), a->model.steady->squared) !=
        a->system.unknowns.end());
  const Answer& omega = answer_named(d, "omega");
  REQUIRE(omega.value);
  CHECK(omega.value->unit == "rpm");
  CHECK(omega.value->approx == Approx(29.3393).epsilon(1e-5));
  CHECK(answer_named(d, "tau").value->approx == Approx(2.04504).epsilon(1e-5));
}

TEST_CASE("Steady: the square itself may be asked for, the rate and period follow", "[steady]") {
  const auto a = test::run_text(pendulum_with("find: [T_BO, omega, tau]", "find: [omega^2]"));
  const Derivation d = explain(*a);
  REQUIRE(d.answers.size() == 3);
  CHECK(d.answers[0].name == "omega^2");
  CHECK(d.answers[0].value->approx == Approx(9.43968).epsilon(1e-5));
  CHECK(d.answers[1].name == "omega");
  CHECK(d.answers[2].name == "tau");
}

TEST_CASE("Steady: where the balances need omega^2 < 0, no rate is reported and the report says why",
          "[steady][validity]") {
  // theta = 120 deg: cos(theta) = -1/2, so omega^2 = g/(L cos(theta)) = -16.35 rad^2/s^2.
  const auto a =
      test::run_text(pendulum_with("theta: {value: 30, unit: deg, range: [10, 80]}", "theta: {value: 120, unit: deg}"));
  const Derivation d = explain(*a);
  CHECK_FALSE(answer_named(d, "omega").value);
  CHECK_FALSE(answer_named(d, "tau").value);
  const auto c = std::find_if(d.conditions.begin(), d.conditions.end(),
                              [](const ConditionReport& r) { return r.source == "steady motion"; });
  REQUIRE(c != d.conditions.end());
  REQUIRE(c->holds);
  CHECK_FALSE(*c->holds);
  CHECK(write(d, Format::text, true)
            .find("This is VIOLATED for the given numbers: no real rate keeps this motion steady.") !=
        std::string::npos);
}

TEST_CASE("Steady: problems are located", "[steady][errors]") {
  CHECK(test::errors_of(pendulum_with("steady: {rate: omega, period: tau}", "steady: {rate: omega, unit: m}")) ==
        Messages{"t.yaml:24:29: 'unit' of 'steady' is a length (expected a rate, such as rad/s or rpm)"});
  CHECK(test::errors_of(pendulum_with("steady: {rate: omega, period: tau}", "steady: {period: tau}"))[0] ==
        "t.yaml:24:9: 'steady' has no 'rate' (expected the name of the unknown rate, e.g. rate: omega)");
  CHECK(test::errors_of(pendulum_with("steady: {rate: omega, period: tau}", "steady: {rate: m}"))[0] ==
        "t.yaml:24:16: duplicate name 'm' (first defined at line 19)");
  CHECK(test::errors_of(pendulum_with("steady: {rate: omega, period: tau}", "steady: {rate: omega, speed: v}")) ==
        Messages{"t.yaml:24:23: unknown key 'speed' in 'steady' (expected one of: rate, unit, period)"});
}
