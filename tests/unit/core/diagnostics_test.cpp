#include <catch2/catch.hpp>

#include "core/diagnostics.hpp"
#include "core/utf8.hpp"

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

TEST_CASE("UTF-8: the first invalid byte is found, valid text passes", "[utf8]") {
  using tackle::invalid_utf8_at;
  CHECK_FALSE(invalid_utf8_at("plain ASCII"));
  CHECK_FALSE(invalid_utf8_at("\xCE\xB8 = 30\xC2\xB0, \xE2\x88\x92x, \xF0\x9F\x98\x80"));  // θ ° − 😀
  CHECK(invalid_utf8_at("caf\xE9!") == 3u);                                                // Latin-1
  CHECK(invalid_utf8_at("ab\xC3") == 2u);                                                  // cut short by the end
  CHECK(invalid_utf8_at("\xC0\xAF") == 0u);                                                // overlong '/'
  CHECK(invalid_utf8_at("x\xED\xA0\x80") == 1u);                                           // a surrogate
  CHECK(invalid_utf8_at("\xF4\x90\x80\x80") == 0u);                                        // above U+10FFFF
  CHECK(invalid_utf8_at("\x80") == 0u);                                                    // a lone continuation byte
}
