// The sparse elimination on the scale benchmarks' shapes (bench/generate.py writes the same
// descriptions), against closed forms derived by hand, and the meaning of its choices.
#include <catch2/catch.hpp>

#include <sstream>

#include "expr/parse.hpp"
#include "expr/print.hpp"
#include "solve/eliminate.hpp"
#include "../../support/helpers.hpp"

using namespace tackle;
using namespace GiNaC;

namespace {

std::string chain(int n) {
  std::ostringstream o;
  o << "title: chain\naxes: [x]\nparameters:\n  F: {unit: N}\n";
  for (int i = 1; i <= n; ++i) o << "  m_" << i << ": {unit: kg}\n";
  o << "bodies:\n";
  for (int i = 1; i <= n; ++i) o << "  b" << i << ": {mass: m_" << i << ", position: x_" << i << "}\n";
  o << "loads: [{on: b" << n << ", force: F}]\nstrings:\n";
  for (int i = 1; i < n; ++i)
    o << "  - {name: s" << i << ", path: [b" << i << ", b" << i + 1 << "], tension: T_" << i << "}\n";
  o << "layout: {";
  for (int i = 1; i <= n; ++i) o << (i > 1 ? ", " : "") << "x_" << i << ": " << 2 * i;
  o << "}\n";
  return o.str();
}

// The answer for `name` minus the expected closed form, in normal form.
ex difference(const Analysis& a, const std::string& name, const std::string& expected) {
  const auto parsed = parse_expression(expected, *a.model.symbols);
  REQUIRE(parsed.value);
  const auto unknown = parse_expression(name, *a.model.symbols);
  REQUIRE(unknown.value);
  const auto value = a.solution.value_of(*unknown.value);
  REQUIRE(value);
  return normal(*value - *parsed.value);
}

}  // namespace

TEST_CASE(
    "Elimination: a chain of 40 blocks gives F over the total mass, and the first k masses' share of F as the k-th "
    "tension",
    "[solve][scale]") {
  const int n = 40;
  const auto a = test::run_text(chain(n));
  REQUIRE(a->solution.status == Solution::Status::determined);
  CHECK(a->solution.rank == 2 * n - 1);
  // By hand: every block has the same acceleration a (the strings stay taut); the blocks
  // 1..k pulled by T_k alone give T_k = (m_1 + ... + m_k) a, and all n by F give F = M a.
  std::string total, partial;
  for (int i = 1; i <= n; ++i) total += (i > 1 ? " + m_" : "m_") + std::to_string(i);
  for (int i = 1; i <= n; ++i)
    CHECK(difference(*a, "ddot(x_" + std::to_string(i) + ")", "F/(" + total + ")").is_zero());
  for (int k = 1; k < n; ++k) {
    partial += (k > 1 ? " + m_" : "m_") + std::to_string(k);
    CHECK(difference(*a, "T_" + std::to_string(k), "(" + partial + ")*F/(" + total + ")").is_zero());
  }
}

TEST_CASE(
    "Elimination: the double Atwood machine gives the textbook tension 8 g m_1 m_2 m_3/(4 m_2 m_3 + m_1 (m_2 + m_3))",
    "[solve][scale]") {
  // Pulley P1 hangs from the ceiling; its string carries B1 and the movable pulley P2, whose
  // string carries B2 and B3 (bench/generate.py cascade 2). By hand, y up: T_1 = 2 T_2
  // (P2 is massless), the string lengths give a_1 = -a_P2 and a_2 + a_3 = 2 a_P2, and the
  // three blocks' balances give T_1 = 8 g m_1 m_2 m_3/D, D = 4 m_2 m_3 + m_1 (m_2 + m_3),
  // and a_1 = g (4 m_2 m_3 - m_1 (m_2 + m_3))/D.
  const auto a = test::run_text(R"(
title: double Atwood
axes: [y]
parameters: {g: {unit: m/s^2}, m_1: {unit: kg}, m_2: {unit: kg}, m_3: {unit: kg}}
gravity: -g
bodies:
  P1: {mass: 0, position: y_P1}
  P2: {mass: 0, position: y_P2}
  B1: {mass: m_1, position: y_1}
  B2: {mass: m_2, position: y_2}
  B3: {mass: m_3, position: y_3}
strings:
  - {name: s1, path: [B1, P1, P2], tension: T_1}
  - {name: s2, path: [B2, P2, B3], tension: T_2}
connections:
  - {type: fixed, body: P1}
  - {type: pulley, at: P1}
  - {type: pulley, at: P2}
layout: {y_P1: 0, y_P2: -2, y_1: -1, y_2: -3, y_3: -3.5}
)");
  REQUIRE(a->solution.status == Solution::Status::determined);
  const std::string D = "(4*m_2*m_3 + m_1*(m_2 + m_3))";
  CHECK(difference(*a, "T_1", "8*g*m_1*m_2*m_3/" + D).is_zero());
  CHECK(difference(*a, "T_2", "4*g*m_1*m_2*m_3/" + D).is_zero());
  CHECK(difference(*a, "ddot(y_1)", "g*(4*m_2*m_3 - m_1*(m_2 + m_3))/" + D).is_zero());
}

namespace {

// bench/generate.py cascade n without the numbers: pulley P_1 hangs from the ceiling; the
// string s_k over P_k carries block B_k and pulley P_(k+1); the last carries B_n and B_(n+1).
std::string cascade(int n) {
  std::ostringstream o;
  o << "title: cascade\naxes: [y]\nparameters:\n  g: {unit: m/s^2}\n";
  for (int i = 1; i <= n + 1; ++i) o << "  m_" << i << ": {unit: kg}\n";
  o << "gravity: -g\nbodies:\n";
  for (int k = 1; k <= n; ++k) o << "  P" << k << ": {mass: 0, position: y_P" << k << "}\n";
  for (int i = 1; i <= n + 1; ++i) o << "  B" << i << ": {mass: m_" << i << ", position: y_" << i << "}\n";
  o << "strings:\n";
  for (int k = 1; k < n; ++k)
    o << "  - {name: s" << k << ", path: [B" << k << ", P" << k << ", P" << k + 1 << "], tension: T_" << k << "}\n";
  o << "  - {name: s" << n << ", path: [B" << n << ", P" << n << ", B" << n + 1 << "], tension: T_" << n << "}\n";
  o << "connections:\n  - {type: fixed, body: P1}\n";
  for (int k = 1; k <= n; ++k) o << "  - {type: pulley, at: P" << k << "}\n";
  o << "layout: {";
  for (int k = 1; k <= n; ++k) o << "y_P" << k << ": " << -2 * (k - 1) << ", ";
  for (int i = 1; i <= n; ++i) o << "y_" << i << ": " << -2 * (i - 1) - 1 << ", ";
  o << "y_" << n + 1 << ": " << -2 * (n - 1) - 1.5 << "}\n";
  return o.str();
}

}  // namespace

TEST_CASE("Elimination: a triple Atwood machine gives T_3 = 8 g/(16/m_1 + 4/m_2 + 1/m_3 + 1/m_4)", "[solve][scale]") {
  // By hand, y up. The massless pulleys P2 and P3 give T_1 = 2 T_2 = 4 T_3. The strings'
  // lengths: a_1 = -a_P2 (P1 is fixed), a_2 + a_P3 = 2 a_P2, a_3 + a_4 = 2 a_P3, so
  // 4 a_1 + 2 a_2 + a_3 + a_4 = 0. Each block: m_k a_k = w_k T_3 - m_k g with
  // w = (4, 2, 1, 1). Then sum w_k a_k = T_3 (16/m_1 + 4/m_2 + 1/m_3 + 1/m_4) - 8 g = 0.
  const auto a = test::run_text(cascade(3));
  REQUIRE(a->solution.status == Solution::Status::determined);
  const std::string S = "(16/m_1 + 4/m_2 + 1/m_3 + 1/m_4)";
  CHECK(difference(*a, "T_3", "8*g/" + S).is_zero());
  CHECK(difference(*a, "T_2", "16*g/" + S).is_zero());
  CHECK(difference(*a, "T_1", "32*g/" + S).is_zero());
  CHECK(difference(*a, "ddot(y_1)", "32*g/(m_1*" + S + ") - g").is_zero());
  CHECK(difference(*a, "ddot(y_2)", "16*g/(m_2*" + S + ") - g").is_zero());
  CHECK(difference(*a, "ddot(y_3)", "8*g/(m_3*" + S + ") - g").is_zero());
  CHECK(difference(*a, "ddot(y_4)", "8*g/(m_4*" + S + ") - g").is_zero());
}

TEST_CASE("Elimination: a cascade of 12 levels gives T_12 = 2^12 g/(sum of 4^(12-k)/m_k)", "[solve][scale]") {
  // The triple machine's argument for n levels: T_k = 2^(n-k) T_n, the lengths give
  // sum w_k a_k = 0 with w_k = 2^(n-k) (w_(n+1) = 1), and m_k a_k = w_k T_n - m_k g, so
  // T_n = g (sum w_k)/(sum w_k^2/m_k) = 2^n g/(sum w_k^2/m_k). The denominators met on the way
  // are products of up to 13 masses (put over them without a gcd: expr/fraction.hpp).
  const int n = 12;
  const auto a = test::run_text(cascade(n));
  REQUIRE(a->solution.status == Solution::Status::determined);
  std::string S = "(";
  for (int k = 1; k <= n + 1; ++k) {
    const long w = k <= n ? (1L << (n - k)) : 1;
    S += (k > 1 ? " + " : "") + std::to_string(w * w) + "/m_" + std::to_string(k);
  }
  S += ")";
  const std::string t_n = "(" + std::to_string(1L << n) + "*g/" + S + ")";
  for (int k = 1; k <= n; ++k)
    CHECK(difference(*a, "T_" + std::to_string(k), std::to_string(1L << (n - k)) + "*" + t_n).is_zero());
  for (int k = 1; k <= n + 1; ++k) {
    const long w = k <= n ? (1L << (n - k)) : 1;
    CHECK(difference(*a, "ddot(y_" + std::to_string(k) + ")",
                     std::to_string(w) + "*" + t_n + "/m_" + std::to_string(k) + " - g")
              .is_zero());
  }
}

TEST_CASE("Elimination: a block-and-tackle of 64 strands gives T = m (F + 65 g m_H)/(m + 4096 m_H)",
          "[solve][scale][string]") {
  // bench/generate.py tackle 64. By hand: the length 64 (y_C - y_M) + (y_C - y_H) gives
  // a_H = -64 a_M; LMB L: 64 T - m g = m a_M; LMB H: T - F - m_H g = m_H a_H. So
  // a_M = (64 F + 64 m_H g - m g)/(m + 4096 m_H) and T = m (F + 65 g m_H)/(m + 4096 m_H).
  std::string path;
  bool at_m = false;  // 64 strands: start at C, so that the 64th ends at C
  for (int i = 0; i <= 64; ++i, at_m = !at_m) path += std::string(i ? ", " : "") + (at_m ? "M" : "C");
  const auto a = test::run_text(R"(
title: block-and-tackle
axes: [y]
parameters: {g: {unit: m/s^2}, m: {unit: kg}, m_H: {unit: kg}, F: {unit: N}}
gravity: -g
bodies: {L: {mass: m, position: y_M}, H: {mass: m_H, position: y_H}}
points: {C: 0, M: {on: L}}
loads: [{on: H, force: -F}]
strings: [{name: rope, path: [)" +
                                path + R"(, H], tension: T}]
connections: [{type: pulley, at: C}, {type: pulley, at: M}]
layout: {y_M: -3, y_H: -1}
)");
  REQUIRE(a->solution.status == Solution::Status::determined);
  CHECK(difference(*a, "T", "m*(F + 65*g*m_H)/(m + 4096*m_H)").is_zero());
  CHECK(difference(*a, "ddot(y_M)", "(64*F + 64*g*m_H - g*m)/(m + 4096*m_H)").is_zero());
  CHECK(difference(*a, "ddot(y_H)", "-64*(64*F + 64*g*m_H - g*m)/(m + 4096*m_H)").is_zero());
}

TEST_CASE("Elimination: in column order the unknown left free is the later one, whatever the sparsest pivot",
          "[solve]") {
  // a + b = 1 and c = 2: b lies in the span of the columns before it, so b is free and
  // a + b = 1 is a combination, even though Markowitz's rule alone could pivot on b.
  const symbol a("a"), b("b"), c("c");
  const std::vector<Equation> eqs{{Equation::Kind::lmb, "first", a + b, 1, {}, {}, "", {}, false},
                                  {Equation::Kind::lmb, "second", c, 2, {}, {}, "", {}, false}};
  const Solution s = solve_equations("t.yaml", eqs, {a, b, c});
  CHECK(s.status == Solution::Status::underdetermined);
  REQUIRE(s.free.size() == 1);
  CHECK(s.free[0].is_equal(b));
  REQUIRE(s.combinations.size() == 1);
  CHECK(to_text(s.combinations[0].combination) == "a + b");
  CHECK(s.value_of(c)->is_equal(2));
}

TEST_CASE("Elimination: an equation left over names the equations it combines", "[solve]") {
  const symbol x("x"), y("y"), p("p");
  SparseSystem s;
  s.columns = 2;
  s.a = {{{0, 1}, {1, 1}}, {{0, 1}, {1, -1}}, {{0, 2}}};
  s.b = {2 * p, 0, 2 * p};
  const Elimination e = eliminate(s, {x, y}, Pivoting::markowitz, true);
  CHECK(e.rank == 2);
  CHECK(normal(e.value[0] - p).is_zero());
  CHECK(normal(e.value[1] - p).is_zero());
  REQUIRE(e.leftover.size() == 1);
  CHECK(is_zero_exactly(e.leftover[0].rhs));
  // The row left over is a combination of all three (x + y, x - y and 2 x are dependent).
  CHECK(e.leftover[0].combination.size() == 3);
}

TEST_CASE(
    "Elimination: a 3-D train of 12 carts joined by ball joints gives each joint the share of the carts behind it",
    "[solve][scale]") {
  // bench/generate.py carts 12. By hand: the carts share a = F/M (M = m_1 + ... + m_12);
  // the joint J_k pushes cart k+1 with -(m_1 + ... + m_k) a along x and nothing across (no
  // moment balances the y and z components about the centers of mass); each floor carries
  // its cart's weight. Every cart's AMB about x reads 0 = 0 and is reported redundant.
  const int n = 12;
  std::ostringstream o;
  o << "title: carts\naxes: [x, y, z]\nparameters: {F: {unit: N}, g: {unit: m/s^2}, b: {unit: m}";
  for (int i = 1; i <= n; ++i) o << ", m_" << i << ": {unit: kg}";
  o << "}\ngravity: [0, 0, -g]\nbodies:\n";
  for (int i = 1; i <= n; ++i)
    o << "  C" << i << ": {mass: m_" << i << ", position: x_" << i << ", center_of_mass: [x_" << i << ", 0, 0]}\n";
  o << "points:\n";
  for (int i = 1; i < n; ++i) o << "  J" << i << ": {on: C" << i + 1 << ", offset: [\"-b\", 0, 0]}\n";
  o << "connections:\n";
  for (int i = 1; i <= n; ++i) o << "  - {type: roller, body: C" << i << ", at: C" << i << ", normal: [0, 0, 1]}\n";
  for (int i = 1; i < n; ++i)
    o << "  - {type: ball_joint, body: C" << i + 1 << ", other: C" << i << ", at: J" << i << "}\n";
  o << "  - {type: force, on: C" << n << ", at: C" << n << ", force: [F, 0, 0]}\nlayout: {";
  for (int i = 1; i <= n; ++i) o << (i > 1 ? ", " : "") << "x_" << i << ": " << 3 * i;
  o << "}\n";
  const auto a = test::run_text(o.str());
  REQUIRE(a->solution.status == Solution::Status::determined);
  CHECK(a->solution.rank == 5 * n - 3);  // n accelerations, n normal forces, 3 (n - 1) joint forces
  CHECK(a->solution.redundant.size() == a->system.equations.size() - a->solution.rank);
  std::string total, partial;
  for (int i = 1; i <= n; ++i) total += (i > 1 ? " + m_" : "m_") + std::to_string(i);
  for (int i = 1; i <= n; ++i) {
    CHECK(difference(*a, "ddot(x_" + std::to_string(i) + ")", "F/(" + total + ")").is_zero());
    CHECK(difference(*a, "N_C" + std::to_string(i), "m_" + std::to_string(i) + "*g").is_zero());
  }
  for (int k = 1; k < n; ++k) {
    partial += (k > 1 ? " + m_" : "m_") + std::to_string(k);
    const std::string j = "J" + std::to_string(k);
    CHECK(difference(*a, j + "_x", "-(" + partial + ")*F/(" + total + ")").is_zero());
    CHECK(difference(*a, j + "_y", "0").is_zero());
    CHECK(difference(*a, j + "_z", "0").is_zero());
  }
}
