// Products made without evaluating (evaluated_quotient): each must be the very object GiNaC's
// own division makes, or nothing.
#include <catch2/catch.hpp>

#include <string>
#include <vector>

#include "expr/pairs.hpp"
#include "expr/print.hpp"
#include "expr/trig.hpp"

using namespace tackle;
using namespace GiNaC;

TEST_CASE("Quotient: made unevaluated only where GiNaC's evaluation would leave it as it is", "[pairs]") {
  const symbol F("F"), g("g"), a("a"), b("b"), x("x");
  std::vector<symbol> m;
  ex total = 0;
  for (int i = 1; i <= 6; ++i) {
    m.emplace_back("m_" + std::to_string(i));
    total += m.back();
  }
  const ex part = m[0] + m[1] + m[2];
  // Each pair: numerator, denominator, whether it is made unevaluated.
  const std::vector<std::tuple<ex, ex, bool>> cases = {
      {F * part, total, true},                         // a chain's tension
      {part, total, true},                             // a sum over a sum
      {3 * F * part, 2 * total * pow(m[3], 2), true},  // numbers and powers of symbols
      {F, total * (m[0] + 1), true},                   // two sums below (the second with a number)
      {2 * m[0] + 2 * m[1], total, false},             // a common factor 2: evaluation takes it out
      {F * (2 * m[0] + 2 * m[1]), total, true},        // (already taken out of the product)
      {F * (m[0] - m[1]), total, true},                // GiNaC's first coefficient decides
      {F * (m[1] - m[0]), total, true},
      {m[0] + m[1] / 2, total, false},    // a fraction in the sum
      {F * pow(total, 2), total, false},  // a base twice
      {F * sqrt(a + b), total, false},    // a root of a sum
      {F * sin(x), total, false},         // a function
      {part, ex(1), false},               // one factor: the factor itself
      {F * part, numeric(2), true},
      {ex(0), total, false},
  };
  int held = 0;
  for (const auto& [num, den, expect_held] : cases) {
    INFO(to_text(num) << " over " << to_text(den));
    const ex usual = num / den;
    const auto made = evaluated_quotient(num, den);
    // The sign rule depends on GiNaC's order of the terms (from addresses): only the cases
    // with no such sum are asked to be made either way.
    const bool sign_case =
        to_text(num).find("- m_") != std::string::npos || to_text(num).find("-m_") != std::string::npos;
    if (!sign_case) CHECK(made.has_value() == expect_held);
    if (made) {
      ++held;
      CHECK(made->is_equal(usual));
      CHECK(made->gethash() == usual.gethash());
      CHECK(to_text(*made) == to_text(usual));
      CHECK((*made - usual).is_zero());
      // A copy without the evaluated flag, evaluated by GiNaC, is the same.
      basic* copy = ex_to<basic>(*made).duplicate();
      copy->setflag(status_flags::dynallocated);  // (the ex made from it owns it)
      copy->clearflag(status_flags::evaluated);
      CHECK(ex(*copy).is_equal(*made));
    }
  }
  CHECK(held >= 6);
}

TEST_CASE("Product: times() is a*b, made unevaluated where GiNaC's evaluation would leave it as it is", "[pairs]") {
  const symbol F("F"), x("x");
  ex total = 0;
  for (int i = 1; i <= 20; ++i) total += symbol("m_" + std::to_string(i));
  const std::vector<std::pair<ex, ex>> cases = {
      {F, total},                  // a chain's tension numerator: made unevaluated
      {3 * F * pow(x, 2), total},  // a monomial with a number
      {numeric(2), total},         // a number times a sum: GiNaC distributes it
      {F, -total},                 // the first coefficient negative: GiNaC takes the sign out
      {F * total, total},          // a base twice: a square
      {x, x},
      {numeric(1), F},
      {F, ex(0)},
      {sin(x), total},  // a function
  };
  for (const auto& [a, b] : cases) {
    INFO(to_text(a) << " times " << to_text(b));
    const ex usual = a * b, made = times(a, b);
    CHECK(made.is_equal(usual));
    CHECK(made.gethash() == usual.gethash());
    CHECK(to_text(made) == to_text(usual));
  }
}

TEST_CASE("Quotient: a sum is primitive when its integer coefficients have no common factor and the first is positive",
          "[pairs]") {
  const symbol a("a"), b("b"), c("c");
  CHECK(primitive_sum(a + b + c));
  CHECK(primitive_sum(a + 2 * b + 1));
  CHECK_FALSE(primitive_sum(2 * a + 4 * b));
  CHECK_FALSE(primitive_sum(2 * a + 4 * b + 6));
  CHECK_FALSE(primitive_sum(a + b / 2));
  CHECK_FALSE(primitive_sum(ex(a)));
  // Exactly one of a - b and b - a starts with a positive coefficient in GiNaC's order.
  CHECK(primitive_sum(a - b) != primitive_sum(b - a));
  // Past a machine integer: decided by CLN.
  const numeric big = numeric(2).power(70);
  CHECK(primitive_sum(a + big * b));
  CHECK_FALSE(primitive_sum(big * a + big * 2 * b));
}

TEST_CASE("Trig: a power of a sin or a cos found through a product's pairs", "[pairs][trig]") {
  const symbol x("x"), m("m");
  CHECK(has_trig_power(m * pow(sin(x), 2) / (m + 1)));
  CHECK_FALSE(has_trig_power(m * sin(x) / (m + 1)));
  CHECK(has_trig(m * sin(x) / (m + 1)));
  CHECK(has_trig_power(m + pow(cos(x), 3)));
  CHECK_FALSE(has_trig(m / (m + 1)));
}

TEST_CASE("Rational polynomial: read from the pairs, as GiNaC's info flag says", "[pairs]") {
  const symbol a("a"), b("b"), c("c");
  const std::vector<ex> cases = {a,
                                 ex(3),
                                 numeric(1, 2),
                                 a + b,
                                 2 * a * b + numeric(1, 3),
                                 pow(a + b, 2) * c,
                                 (a + b) / 2,
                                 a / b,
                                 pow(a, -2) + b,
                                 sqrt(a) + b,
                                 sin(a) * b,
                                 a * sqrt(ex(2)),
                                 pow(a + 1, 3) - pow(b, 4) * c + 7,
                                 ex(numeric(2).power_dyn(numeric(1, 2))) * a,
                                 Pi * a,
                                 numeric(1.5) * a,
                                 pow(a + b, numeric(1, 2))};
  for (const ex& e : cases) {
    INFO(e);
    CHECK(rational_polynomial(e) == e.info(info_flags::rational_polynomial));
  }
}

TEST_CASE("Expanded polynomial: recognised only where expand() would give it back", "[pairs]") {
  const symbol a("a"), b("b"), c("c");
  const std::vector<std::pair<ex, bool>> cases = {{a, true},
                                                  {ex(3), true},
                                                  {a * b + 2 * c, true},
                                                  {pow(a, 3) * b - 5, true},
                                                  {a * b * c + a + numeric(1, 2), true},
                                                  {(a + b) * c, false},
                                                  {pow(a + b, 2), false},
                                                  {a / b + c, false},
                                                  {sqrt(a) + b, false},
                                                  {sin(a) * b, false}};
  for (const auto& [e, expected] : cases) {
    INFO(e);
    CHECK(expanded_polynomial(e) == expected);
    if (expanded_polynomial(e)) CHECK(e.expand().is_equal(e));
  }
}
