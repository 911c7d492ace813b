#include <catch2/catch.hpp>

#include "core/diagnostics.hpp"

using namespace tackle;

TEST_CASE("Diagnostics: file:line:col: message, parts left out when unknown", "[core]") {
  CHECK(format({{"a.yaml", 12, 5}, "unknown body 'Q'"}) == "a.yaml:12:5: unknown body 'Q'");
  CHECK(format({{"a.yaml", 12, 0}, "m"}) == "a.yaml:12: m");
  CHECK(format({{"a.yaml", 0, 0}, "m"}) == "a.yaml: m");
  CHECK(format({{"", 0, 0}, "m"}) == "m");
}

TEST_CASE("Diagnostics: all problems are collected, then thrown at once", "[core]") {
  Diagnostics d;
  d.error({"f", 1, 1}, "first");
  d.error({"f", 2, 1}, "second");
  try {
    d.throw_if_any();
    FAIL("expected an InputError");
  } catch (const InputError& e) {
    REQUIRE(e.diagnostics().size() == 2);
    CHECK(e.diagnostics()[1].message == "second");
  }
}

TEST_CASE("Diagnostics: the nearest name is suggested only when it is close", "[core]") {
  CHECK(nearest("mas", {"mass", "position"}) == "mass");
  CHECK(nearest("pully", {"force", "fixed", "pulley", "string"}) == "pulley");
  CHECK(nearest("M_a", {"m_A", "m_B"}) == "m_A");
  CHECK(nearest("zzzzzz", {"mass", "position"}).empty());
}
