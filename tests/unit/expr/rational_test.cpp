#include <catch2/catch.hpp>

#include <algorithm>
#include <cstdint>
#include <string>
#include <thread>
#include <vector>

#include <cln/integer.h>
#include <cln/modinteger.h>

#include "expr/memory.hpp"
#include "expr/rational.hpp"
#include "expr/trig.hpp"

using namespace tackle;
using namespace GiNaC;

namespace {

// n modulo 2^61 - 1, by hand: the values below are small enough to write out.
std::uint64_t mod(long n) {
  const long p = static_cast<long>(ModularPoint::prime);
  return static_cast<std::uint64_t>(((n % p) + p) % p);
}

}  // namespace

TEST_CASE("Modular: a rational function at given values is its value modulo 2^61 - 1", "[rational]") {
  const symbol a("a"), b("b"), c("c");
  ModularPoint point(1);
  point.values[a] = 3;
  point.values[b] = 5;
  point.values[c] = 7;
  // (a + 2 b)^3 - c a b = 13^3 - 105 = 2092
  const ModularAt r = modular_at(pow(a + 2 * b, 3) - c * a * b, point);
  REQUIRE(r.kind == RationalAt::Kind::value);
  CHECK(r.value == mod(2092));
  // -(a + b) / 4: -2 modulo the prime.
  const ModularAt q = modular_at(-(a + b) / 4, point);
  REQUIRE(q.kind == RationalAt::Kind::value);
  CHECK(q.value == mod(-2));
  // 1/2 times 2 is 1: the inverse is exact modulo the prime.
  CHECK(modular_at(numeric(1, 2) * 2 * a / a, point).value == 1);
  CHECK(modular_quotient(mod(-12), 4) == mod(-3));
  CHECK(modular_negated(0) == 0);
}

TEST_CASE("Modular: a vanishing denominator is a pole, a function is not rational", "[rational]") {
  const symbol a("a"), b("b");
  ModularPoint point(1);
  point.values[a] = 4;
  point.values[b] = 4;
  CHECK(modular_at(1 / (a - b), point).kind == RationalAt::Kind::pole);
  CHECK(modular_at(pow(a - b, -2) * a, point).kind == RationalAt::Kind::pole);
  CHECK(modular_at(sin(a), point).kind == RationalAt::Kind::other);
  CHECK(modular_at(sqrt(a), point).kind == RationalAt::Kind::other);
  // 0^0 = 1, 0^3 = 0.
  CHECK(modular_at(pow(a - b, 3) + 1, point).value == 1);
}

TEST_CASE("Modular: values drawn from names are the same for every expression and seed", "[rational]") {
  const symbol m1("m_1"), m2("m_2");
  ModularPoint one(7), two(7), other(8);
  const ModularAt x = modular_at(m1, one), y = modular_at(m1 + 0 * m2, two), z = modular_at(m1, other);
  CHECK(x.value == y.value);
  CHECK(x.value == static_cast<std::uint64_t>(drawn_value("m_1", 7).to_long()));
  CHECK(x.value >= 1);
  CHECK(x.value <= (std::uint64_t{1} << 40));
  CHECK(x.value != z.value);
}

TEST_CASE("Zero at random points: zero, not zero, and not a rational function", "[rational]") {
  const symbol m("m"), M("M"), F("F"), a("a");
  // a = F/(m + M) put in (m + M) a - F.
  const exmap solution{{a, F / (m + M)}};
  CHECK(zero_at_random_points((m + M) * a - F, {&solution}) == std::optional<bool>(true));
  CHECK(zero_at_random_points(m * a - F, {&solution}) == std::optional<bool>(false));
  CHECK(zero_at_random_points(sin(m) - sin(m)) == std::optional<bool>(true));  // GiNaC makes it 0
  CHECK_FALSE(zero_at_random_points(sin(m) * a - F, {&solution}).has_value());
  // (m + M)^2 - m^2 - 2 m M - M^2 is zero; with one sign wrong it is not.
  CHECK(zero_at_random_points(pow(m + M, 2) - pow(m, 2) - 2 * m * M - pow(M, 2)) == std::optional<bool>(true));
  CHECK(zero_at_random_points(pow(m + M, 2) - pow(m, 2) + 2 * m * M - pow(M, 2)) == std::optional<bool>(false));
}

TEST_CASE("Rational at: exact values and poles", "[rational]") {
  const symbol a("a"), b("b");
  RationalPoint point{{a, numeric(1, 3)}, {b, numeric(2)}};
  const RationalAt r = rational_at(pow(a, -2) + b / 4, point);
  REQUIRE(r.kind == RationalAt::Kind::value);
  CHECK(r.value == numeric(19, 2));
  RationalPoint zero{{a, numeric(2)}, {b, numeric(2)}};
  CHECK(rational_at(1 / (a - b), zero).kind == RationalAt::Kind::pole);
  // The same from an exmap; a value that is not a number is not given.
  const exmap values{{a, numeric(1, 3)}, {b, numeric(2)}};
  const RationalAt m = rational_at(pow(a, -2) + b / 4, values);
  REQUIRE(m.kind == RationalAt::Kind::value);
  CHECK(m.value == numeric(19, 2));
  CHECK(rational_at(1 / (a - b), exmap{{a, numeric(2)}, {b, numeric(2)}}).kind == RationalAt::Kind::pole);
  CHECK(rational_at(a + b, exmap{{a, numeric(1)}, {b, a}}).kind == RationalAt::Kind::other);
  CHECK(rational_at(a + b, exmap{{a, numeric(1)}}).kind == RationalAt::Kind::other);
}

TEST_CASE("Rational at: long sums' values remembered at a point give the same values", "[rational]") {
  const symbol F("F");
  RationalPoint point{{F, numeric(10)}};
  ex M = 0, S = 0;
  for (int i = 1; i <= 20; ++i) {
    const symbol m("m_" + std::to_string(i));
    point.emplace(m, numeric(i, 2));  // m_i = i/2: M = 105, S = m_2 + ... + m_20 = 104.5
    M += m;
    if (i > 1) S += m;
  }
  SumValues sums;
  for (const ex& e : {F / M, F * S / M, F * S / M, ex(M)}) {
    const RationalAt plain = rational_at(e, point), kept = rational_at(e, point, sums);
    REQUIRE(kept.kind == RationalAt::Kind::value);
    CHECK(kept.value == plain.value);
  }
  CHECK(rational_at(F * S / M, point, sums).value == numeric(209, 21));  // 10 * 104.5 / 105
  // The two long sums are remembered; nothing shorter than 17 terms.
  CHECK(sums.values.size() == 2);
  CHECK(sums.values.at(M) == numeric(105));
  CHECK(rational_at(F * M + F, point, sums).value == numeric(1060));
  CHECK(sums.values.size() == 2);
  CHECK(rational_at(F + M, point, sums).value == numeric(115));  // one sum of 21 terms
  CHECK(sums.values.size() == 3);
}

TEST_CASE("Trig: sin and cos and their powers found by structure", "[rational]") {
  const symbol t("theta"), m("m");
  CHECK(has_trig(m * cos(t) + 1));
  CHECK_FALSE(has_trig(m * exp(t)));
  CHECK(has_trig_power(m * pow(sin(t), 2) + 1));
  CHECK_FALSE(has_trig_power(m * sin(t) + cos(t)));
  CHECK(has_trig_power(1 / (m + pow(cos(t), 3))));
}

TEST_CASE("Modular: a long sum remembered is forgotten when a value it used changes", "[rational]") {
  ex sum = 0;
  std::vector<symbol> m;
  for (int i = 1; i <= 9; ++i) m.emplace_back("m_" + std::to_string(i));
  for (const auto& s : m) sum += s;
  ModularPoint point(1);
  for (const auto& s : m) point.assign(s, 1);
  CHECK(modular_at(sum, point).value == 9);
  CHECK(modular_at(2 / sum, point).value == modular_quotient(2, 9));  // the same node, remembered
  point.assign(m[0], 10);
  CHECK(modular_at(sum, point).value == 18);
}

namespace {

// The count node_count() keeps to: GiNaC's own operands, op() by op().
std::size_t nodes_by_op(const ex& e) {
  std::size_t n = 1;
  for (std::size_t i = 0; i < e.nops(); ++i) n += nodes_by_op(e.op(i));
  return n;
}

}  // namespace

TEST_CASE("Node count: read from the stored pairs, the same as op() by op()", "[rational]") {
  const possymbol m1("m_1"), m2("m_2"), m3("m_3"), F("F"), g("g");
  const symbol x("x"), y("y");
  ex M = 0;
  for (const auto& s : {m1, m2, m3}) M += s;
  const std::vector<ex> forms{
      F / M,
      -F * (m2 + m3) / M,
      3 * m1 - 2 * m2 * m3 + 7,
      pow(m1 + 2 * m2, 2) * x / (pow(y, 3) * (m1 - m3)),
      2 * x * y + numeric(1, 2) * pow(x, 2) - 5,
      sqrt(2) * x / (3 * pow(g, numeric(1, 2))),
      -g * (m1 - m2) / (m1 + m2) + sin(x) * pow(cos(x), 2),
      (F - 4 * g * m1 * m2) / pow(M, 3) + 1,
  };
  for (const ex& e : forms) {
    CAPTURE(e);
    CHECK(node_count(e) == nodes_by_op(e));
    CHECK(node_count(e, 5) == std::min<std::size_t>(5, nodes_by_op(e)));
  }
}

TEST_CASE("Content: the integer and monomial content, and the rest term by term as expand() gives it", "[rational]") {
  const symbol F("F"), g("g"), x("x"), y("y"), m1("m_1"), m2("m_2"), m3("m_3");
  // Worked by hand: the content and the rest of each.
  struct Case {
    ex p, content, rest;
  };
  const std::vector<Case> cases{
      {F * m1 + F * m2 + F * m3, F, m1 + m2 + m3},
      {6 * F * pow(x, 2) * y + 4 * F * x * pow(y, 3), 2 * F * x * y, 3 * x + 2 * pow(y, 2)},
      {numeric(3, 4) * x * g + numeric(9, 2) * x, numeric(3, 4) * x, g + 6},
      {pow(x, 3) + pow(x, 5), pow(x, 3), 1 + pow(x, 2)},
      {x * y + 2, 1, x * y + 2},
      {-2 * x - 4 * x * y, 2 * x, -1 - 2 * y},
      {x + y, 1, x + y},
      {5 * pow(x, 2) * y, 5 * pow(x, 2) * y, 1},
  };
  for (const auto& c : cases) {
    const ex p = c.p.expand();
    const Content got = content_of(p);
    CHECK(got.content.is_equal(c.content));
    CHECK(got.rest.is_equal(c.rest));
    // The same objects the formula it replaces makes, and the same lowest degrees.
    ex monomial = p.integer_content();
    for (const auto& [s, k] : degrees_of(p).low) monomial *= pow(s, k);
    CHECK(got.content.is_equal(monomial));
    CHECK(got.rest.is_equal((p / monomial).expand()));
    CHECK(got.rest.gethash() == (p / monomial).expand().gethash());
    CHECK(low_degrees(p) == degrees_of(p).low);
  }
  // A sum over 256 masses, each times F: F and the sum of the masses.
  ex sum = 0, masses = 0;
  for (int i = 1; i <= 256; ++i) {
    const symbol m("m_" + std::to_string(i));
    sum += F * m;
    masses += m;
  }
  const Content big = content_of(sum);
  CHECK(big.content.is_equal(F));
  CHECK(big.rest.is_equal(masses));
}

TEST_CASE("Content of a product: a monomial times a long primitive sum, as content_of() of its expansion",
          "[rational]") {
  const symbol F("F"), x("x"), s("s");
  ex masses = 0;
  for (int i = 1; i <= 20; ++i) masses += symbol("m_" + std::to_string(i));
  const ex wide = masses + 3 * s * x - 2;  // integer coefficients without a common factor
  // Worked by hand: |k| x^a ..., and the sum (negated for k < 0).
  struct Case {
    ex p, content, rest;
  };
  const std::vector<Case> cases{
      {F * masses, F, masses},
      {-3 * pow(F, 2) * x * wide, 3 * pow(F, 2) * x, -wide},
      {7 * x * wide, 7 * x, wide},
  };
  for (const auto& c : cases) {
    const auto got = content_of_product(c.p, factor_term_limit);
    REQUIRE(got);
    CHECK(got->content.is_equal(c.content));
    CHECK(got->rest.is_equal(c.rest));
    // The same as the expansion's content.
    const Content expanded = content_of(c.p.expand());
    CHECK(got->content.is_equal(expanded.content));
    CHECK(got->rest.is_equal(expanded.rest));
  }
  // Not that shape: nothing.
  ex short_sum = 0;
  for (int i = 1; i <= 16; ++i) short_sum += symbol("n_" + std::to_string(i));
  CHECK_FALSE(content_of_product(F * short_sum, factor_term_limit));              // 16 terms, not more
  CHECK_FALSE(content_of_product(F * (x * masses).expand(), factor_term_limit));  // x in every term
  CHECK_FALSE(content_of_product(F * masses * wide, factor_term_limit));          // two sums
  CHECK_FALSE(content_of_product(sin(x) * masses, factor_term_limit));            // a function
  CHECK_FALSE(content_of_product(masses / 3 * F, factor_term_limit));             // not an integer
  CHECK_FALSE(content_of_product(masses, factor_term_limit));                     // not a product
  CHECK_FALSE(content_of_product(pow(F, -1) * masses, factor_term_limit));        // a negative power
}

TEST_CASE("Common monomial: the least power of each symbol that is a factor of every term", "[rational]") {
  const symbol F("F"), x("x"), a("a"), b("b"), m3("m_3");
  CHECK(common_monomial({F * (a + b), -m3 * F, 0}).is_equal(F));
  CHECK(common_monomial({pow(F, 2) * x, F * pow(x, 3) * (a + b)}).is_equal(F * x));
  CHECK(common_monomial({2 * pow(x, 2), -x}).is_equal(x));
  CHECK(common_monomial({a + b, F}).is_equal(1));  // a sum holds no symbol as a factor
  CHECK(common_monomial({F, x}).is_equal(1));
  CHECK(common_monomial({}).is_equal(1));
  CHECK(common_monomial({0, 0}).is_equal(1));
}

TEST_CASE("Modular: integers and exponents past 62 bits and negative ones, as CLN's modular ring gives them",
          "[rational]") {
  const symbol x("x");
  const cln::cl_modint_ring R = cln::find_modint_ring(cln::cl_I(static_cast<unsigned long>(ModularPoint::prime)));
  const cln::cl_I two62 = cln::expt_pos(cln::cl_I(2), 62), two70 = cln::expt_pos(cln::cl_I(2), 70);
  const std::vector<cln::cl_I> coefficients{
      -1, 3, -two62, two62 - 1, two62, two70 + 5, -two70, cln::cl_I(static_cast<unsigned long>(ModularPoint::prime))};
  const std::vector<cln::cl_I> exponents{1, -1, 5, -7, two62 + 3, -(two70 + 1)};
  for (const auto& c : coefficients)
    for (const auto& k : exponents) {
      ModularPoint point(1);
      point.values[x] = 3;
      const ex e = numeric(cln::cl_N(c)) * pow(x, numeric(cln::cl_N(k)));
      const ModularAt got = modular_at(e, point);
      REQUIRE(got.kind == RationalAt::Kind::value);
      const cln::cl_MI three = R->canonhom(3);
      const cln::cl_MI power = cln::minusp(k) ? cln::recip(cln::expt_pos(three, -k)) : cln::expt_pos(three, k);
      const cln::cl_MI want = R->canonhom(c) * power;
      CHECK(cln::cl_I(static_cast<unsigned long>(got.value)) == R->retract(want));
    }
}

TEST_CASE("Normal form: sums over and under the line cancelled through their contents, the same as normal()",
          "[rational]") {
  const symbol a("a"), b("b"), c("c"), d("d"), e("e"), m("m"), x("x"), y("y"), z("z");
  const ex l = sqrt(pow(b, 2) + pow(d, 2) + pow(e, 2));
  // Each worked by hand; normal_remembered() must give what normal() gives.
  const std::vector<std::pair<ex, ex>> cases{
      // Sample 12.8: a m (c - e)/2 over -d (e - c)/l is a m l/(2 d); over d (e - c)/l, its negative.
      {(a * m * c / 2 - a * m * e / 2) / (-(d * e - c * d) * pow(l, -1)), a * m * l / (2 * d)},
      {(a * m * c / 2 - a * m * e / 2) / ((d * e - c * d) * pow(l, -1)), -a * m * l / (2 * d)},
      {(2 * x * y + 2 * x * z) / (4 * y + 4 * z), x / 2},
      {(c - e) / (e - c), -1},
      {pow(a * c - a * e, 2) / pow(c * d - d * e, 3), pow(a, 2) / (pow(d, 3) * (c - e))},
      // Nothing in common: left as normal() leaves it.
      {(pow(x, 2) - pow(y, 2)) / (x - y), x + y},
      {(x + y) / (x + z), (x + y) / (x + z)},
  };
  for (const auto& [q, want] : cases) {
    const ex got = normal_remembered(q);
    CHECK(got.is_equal(normal(q)));
    CHECK(normal(got - want).is_zero());
  }
}

TEST_CASE("Memory: each kind of memory is its own, one per thread, made empty", "[expr]") {
  struct first_kind;
  struct second_kind;
  auto& a = tackle::thread_memory<first_kind, std::vector<int>>();
  auto& b = tackle::thread_memory<second_kind, std::vector<int>>();
  CHECK(&a != &b);
  CHECK(&a == &tackle::thread_memory<first_kind, std::vector<int>>());
  a.push_back(7);
  CHECK(b.empty());
  CHECK(tackle::thread_memory<struct a_count, std::size_t>() == 0);
  // Another thread gets its own, empty.
  std::size_t seen = 99;
  const std::vector<int>* theirs = nullptr;
  std::thread([&] {
    seen = tackle::thread_memory<first_kind, std::vector<int>>().size();
    theirs = &tackle::thread_memory<first_kind, std::vector<int>>();
  }).join();
  CHECK(seen == 0);
  CHECK(theirs != &a);
  CHECK(a == std::vector<int>{7});
}
