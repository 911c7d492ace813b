#include <catch2/catch.hpp>

#include "expr/print.hpp"
#include "../../support/helpers.hpp"

using namespace tackle;

namespace {
std::vector<std::string> solved_forms(const ConditionReport& c) {
  std::vector<std::string> out;
  for (const auto& s : c.solved) out.push_back(to_text(s.parameter) + " " + s.op + " " + to_text(s.bound));
  return out;
}
}  // namespace

TEST_CASE("Validity: the suitcase's trailing contact pushes exactly when l >= 2 mu h", "[validity]") {
  const auto a = analyze_file(TACKLE_SOURCE_DIR "/examples/sample-12.7-suitcase.yaml", test::rules());
  const Derivation d = explain(*a);
  REQUIRE(d.conditions.size() == 2);
  const ConditionReport& na = d.conditions[0];
  CHECK(na.source == "sliding at A");
  CHECK(to_text(na.simplified) == "g*m*(l - 2*h*mu)/(2*l)");
  CHECK(solved_forms(na) == std::vector<std::string>{"mu <= l/(2*h)", "l >= 2*h*mu", "h <= l/(2*mu)"});
  REQUIRE(na.holds);
  CHECK(*na.holds);
  const ConditionReport& nb = d.conditions[1];
  REQUIRE(nb.always);
  CHECK(*nb.always);
}

TEST_CASE("Validity: a tall suitcase tips, and the report says so", "[validity]") {
  const auto a = test::run_text(test::example_with("sample-12.7-suitcase.yaml", "h: {value: 0.4,", "h: {value: 1.5,"));
  const Derivation d = explain(*a);
  REQUIRE(d.conditions[0].holds);
  CHECK_FALSE(*d.conditions[0].holds);
  CHECK(d.conditions[0].otherwise == "the body lifts off the contact (it tips)");
  CHECK(write(d, Format::text, false).find("warning: sliding at A: the body lifts off the contact (it tips)") !=
        std::string::npos);
}

TEST_CASE("Validity: braking on the front wheels lifts the rear when d < mu h", "[validity]") {
  const auto a = test::run_text(
      test::example_with("car-braking-front.yaml", "h: {value: 0.5, unit: m}", "h: {value: 2.5, unit: m}"));
  const Derivation d = explain(*a);
  const auto rear = std::find_if(d.conditions.begin(), d.conditions.end(),
                                 [](const ConditionReport& c) { return c.source == "free_wheel at R"; });
  REQUIRE(rear != d.conditions.end());
  REQUIRE(rear->holds);
  CHECK_FALSE(*rear->holds);
  CHECK(rear->otherwise == "the wheel lifts off");
}

TEST_CASE("Validity: a condition is solved for a parameter only when a coefficient's sign is known", "[validity]") {
  const GiNaC::possymbol l("l"), h("h");
  const GiNaC::realsymbol mu("mu"), x("x");
  // mu's coefficient -2 h has a known sign, h's coefficient -2 mu does not (mu is not
  // declared positive here).
  const auto s = solve_condition(l - 2 * h * mu, ">=", {mu, l, h});
  REQUIRE(s.size() == 2);
  CHECK(to_text(s[0].parameter) + " " + s[0].op + " " + to_text(s[0].bound) == "mu <= l/(2*h)");
  CHECK(to_text(s[1].parameter) + " " + s[1].op + " " + to_text(s[1].bound) == "l >= 2*h*mu");
  CHECK(solve_condition(x * x - 1, ">=", {x}).empty());  // not linear
}
