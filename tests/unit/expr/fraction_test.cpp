// normal_by_factors: fractions over products of irreducible factors put in normal form
// without a gcd, against normal forms worked out by hand.
#include <catch2/catch.hpp>

#include <string>

#include "expr/fraction.hpp"
#include "expr/print.hpp"

using namespace tackle;
using namespace GiNaC;

TEST_CASE("Fractions by factors: a sum over symbols goes over their product, as normal() leaves it", "[rational]") {
  const symbol a("a"), b("b"), m_1("m_1"), m_2("m_2");
  // a/m_1 + b/m_2 = (a m_2 + b m_1)/(m_1 m_2): nothing cancels (neither m divides it).
  const auto q = normal_by_factors(a / m_1 + b / m_2);
  REQUIRE(q);
  CHECK(q->is_equal((a * m_2 + b * m_1) / (m_1 * m_2)));
  CHECK(q->is_equal(normal(a / m_1 + b / m_2)));
  // a/(2 m_1) + a/(3 m_1) = 5 a/(6 m_1): the numbers go under the line as normal() puts them.
  const auto r = normal_by_factors(a / (2 * m_1) + a / (3 * m_1));
  REQUIRE(r);
  CHECK(r->is_equal(normal(a / (2 * m_1) + a / (3 * m_1))));
  CHECK(normal(*r - 5 * a / (6 * m_1)).is_zero());
}

TEST_CASE("Fractions by factors: a symbol cancels as far as its lowest power over the line", "[rational]") {
  const symbol a("a"), b("b"), x("x"), y("y");
  // (x^2 a + x^3 b)/(x^3 y) = (a + x b)/(x y): x^2 divides every term, x^3 does not.
  const auto q = normal_by_factors((pow(x, 2) * a + pow(x, 3) * b) * pow(x, -3) * pow(y, -1));
  REQUIRE(q);
  CHECK(q->is_equal((a + x * b) / (x * y)));
  // x/(x y) in parts: x * (1/(x y)) = 1/y.
  const auto r = normal_by_factors(x * (a / x + b / (x * y)) - a);
  REQUIRE(r);
  CHECK(r->is_equal(b / y));
}

TEST_CASE("Fractions by factors: an irreducible sum divides out when it divides the numerator", "[rational]") {
  const symbol m_1("m_1"), m_2("m_2"), g("g");
  // (m_1^2 - m_2^2)/(m_1 + m_2) = m_1 - m_2, written as a sum of two fractions.
  const ex s = m_1 + m_2;
  const auto q = normal_by_factors(pow(m_1, 2) / s - pow(m_2, 2) / s);
  REQUIRE(q);
  CHECK(q->is_equal(m_1 - m_2));
  // g m_1/(m_1 + m_2) + g m_2/(m_1 + m_2) = g.
  const auto r = normal_by_factors(g * m_1 / s + g * m_2 / s);
  REQUIRE(r);
  CHECK(r->is_equal(g));
  // The content of a sum under the line comes out as GiNaC's evaluation takes it out:
  // 1/(2 m_1 + 2 m_2) + 1/(m_1 + m_2) = 3/(2 (m_1 + m_2)).
  const auto c = normal_by_factors(1 / (2 * m_1 + 2 * m_2) + 1 / s);
  REQUIRE(c);
  CHECK(normal(*c - ex(3) / (2 * s)).is_zero());
}

TEST_CASE("Fractions by factors: what equals zero is exactly 0", "[rational]") {
  const symbol a("a"), b("b"), m_1("m_1"), m_2("m_2");
  const ex e = a / m_1 + b / m_2 - (a * m_2 + b * m_1) / (m_1 * m_2);
  const auto q = normal_by_factors(e);
  REQUIRE(q);
  CHECK(q->is_equal(0));
}

TEST_CASE("Fractions by factors: nothing when a denominator's factors are not known", "[rational]") {
  const symbol a("a"), m_1("m_1"), m_2("m_2"), m_3("m_3"), x("x");
  // m_1 m_2 + m_1 m_3 = m_1 (m_2 + m_3), expanded: not known to be irreducible.
  CHECK_FALSE(normal_by_factors(a / (m_1 * m_2 + m_1 * m_3)));
  // x^2 - 1 = (x - 1)(x + 1): of degree 2 in its only symbol.
  CHECK_FALSE(normal_by_factors(a / (pow(x, 2) - 1)));
  // Not a rational function of symbols.
  CHECK_FALSE(normal_by_factors(sin(x) / m_1));
  CHECK_FALSE(normal_by_factors(sqrt(x) / m_1));
}

TEST_CASE("Fractions by factors: a fraction of fractions, inverted when its numerator's factors are known",
          "[rational]") {
  const symbol g("g"), m_1("m_1"), m_2("m_2");
  // The double Atwood's effective mass, by hand: 1/(1/m_1 + 1/m_2) = m_1 m_2/(m_1 + m_2), and
  // g/(1/m_1 + 1/m_2) is g m_1 m_2/(m_1 + m_2).
  const auto q = normal_by_factors(g * pow(1 / m_1 + 1 / m_2, -1));
  REQUIRE(q);
  CHECK(normal(*q - g * m_1 * m_2 / (m_1 + m_2)).is_zero());
  CHECK(q->is_equal(normal(g * pow(1 / m_1 + 1 / m_2, -1))));
}
