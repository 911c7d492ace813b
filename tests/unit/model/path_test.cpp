// The root of a perfect square (model/path.hpp), the lengths of segments and of inertial
// arrows come out of: by hand.
#include <catch2/catch.hpp>

#include "model/path.hpp"

using namespace tackle;
using namespace GiNaC;

TEST_CASE("Square root: numbers, fractions and even powers come out of the root", "[path]") {
  const symbol L("L"), w("dot(theta)"), a("a"), b("b");
  // L^2 w^4/4: a quarter, L squared, w to the fourth: L w^2/2 (to_polynomial stands a symbol
  // for the 1/4; the root reads it back).
  const auto quarter = square_root_of(pow(L, 2) * pow(w, 4) / 4);
  REQUIRE(quarter);
  CHECK((*quarter - L * pow(w, 2) / 2).expand().is_zero());
  // (a + b)^2 = a^2 + 2 a b + b^2: a + b (up to its sign).
  const auto sum = square_root_of(pow(a, 2) + 2 * a * b + pow(b, 2));
  REQUIRE(sum);
  CHECK((pow(*sum, 2) - pow(a + b, 2)).expand().is_zero());
  // 9 sin(a)^2: 3 sin(a).
  const auto trig = square_root_of(9 * pow(sin(a), 2));
  REQUIRE(trig);
  CHECK((*trig - 3 * sin(a)).expand().is_zero());
  // Not squares: a^2 + b^2, 2 a^2 L (an odd power), -a^2.
  CHECK(!square_root_of(pow(a, 2) + pow(b, 2)));
  CHECK(!square_root_of(2 * pow(a, 2) * L));
  CHECK(!square_root_of(-pow(a, 2)));
}
