#include <catch2/catch.hpp>

#include <string>
#include <vector>

#include "expr/print.hpp"
#include "../../support/helpers.hpp"

using namespace tackle;

TEST_CASE("Solve: a free unknown is named when the equations do not fix it", "[solve]") {
  const auto a = test::run_text(R"(
title: one balance, two unknowns
parameters: {m: {unit: kg}}
bodies: {A: {mass: m, position: x_A}, B: {mass: 0, position: x_B}}
strings: [{name: s, path: [A, B], tension: T}]
layout: {x_A: 0, x_B: 1}
derive: [{lmb: A}]
)");
  CHECK(a->solution.status == Solution::Status::underdetermined);
  REQUIRE(a->solution.free.size() == 1);
  CHECK(to_text(a->solution.free[0]) == "T");
  REQUIRE(a->solution.combinations.size() == 1);
  CHECK(to_text(a->solution.combinations[0].combination) == "ddot(x_A) - T/m");
}

TEST_CASE("Solve: an inconsistent system names the conflicting equations", "[solve]") {
  const std::string text = R"(
title: a massless block pulled by a force and nothing else
parameters: {F: {unit: N}}
bodies: {A: {mass: 0, position: x_A}}
loads: [{on: A, force: F}]
)";
  // The solver names the equation that cannot hold ...
  const Description d = parse_description(text, "t.yaml");
  const RuleSet& rules = test::rules();
  const Model m = build_model(d, rules);
  const EquationSystem s = build_equations(m);
  const Solution sol = solve(m, s);
  CHECK(sol.status == Solution::Status::inconsistent);
  CHECK(sol.conflicts == std::vector<std::string>{"LMB A (x)"});
  // ... and the pipeline refuses the description (exit 1), at the body, with what could supply it.
  CHECK(test::errors_of(text) ==
        std::vector<std::string>{
            "t.yaml:4:10: the balances cannot all hold: LMB A (x) reads 0 = a force that is not zero (expected "
            "body 'A' has no mass, so the forces on it must cancel: a support, a string or a contact that "
            "balances them, or a mass)"});
}

TEST_CASE("Solve: a system balance next to the body balances is reported redundant", "[solve]") {
  const auto a = test::run_text(R"(
title: towing, every balance
parameters: {F: {unit: N}, m_1: {unit: kg}, m_2: {unit: kg}}
bodies: {car1: {mass: m_1, position: x_1}, car2: {mass: m_2, position: x_2}}
loads: [{on: car2, force: F}]
strings: [{name: chain, path: [car1, car2], tension: T}]
layout: {x_1: 0, x_2: 1}
derive: [{lmb: car1}, {lmb: car2}, {lmb: [car1, car2]}, {constraint: chain}]
)");
  CHECK(a->solution.status == Solution::Status::determined);
  CHECK(a->solution.rank == 3);
  REQUIRE(a->solution.redundant.size() == 1);
  CHECK(a->solution.redundant[0] ==
        std::vector<std::string>{"LMB car1 (x)", "LMB car2 (x)", "LMB of the system {car1, car2} (x)"});
}

TEST_CASE("Pulley: three strands at B give a third of the travel", "[string]") {
  const auto a = test::run_text(R"(
title: three strands at B, one at A
bodies: {A: {position: x_A}, B: {position: x_B}}
points: {C: 0, pB: {on: B}}
strings: [{name: s, path: [A, C, pB, C, pB]}]
connections: [{type: pulley, at: C}]
layout: {x_A: -1, x_B: 1}
derive: [{constraint: s}]
given: [ddot(x_A)]
)");
  REQUIRE(a->solution.values.size() == 1);
  CHECK(to_text(a->solution.values[0].unknown) == "ddot(x_B)");
  CHECK(to_text(a->solution.values[0].value) == "ddot(x_A)/3");
}

TEST_CASE("Dimensions: every written equation is checked, naming the term that disagrees", "[solve][units]") {
  RuleSet rules = load_rules(TACKLE_SOURCE_DIR "/rules");
  // A rule whose force argument declares no dimension: only the equation check can catch it.
  rules.add(
      parse_rule("type: push\nneeds: {on: body, amount: expr}\nloads:\n  - {on: on, force: amount}\n", "push.yaml"));
  const std::string text = R"(title: a push given in metres
parameters: {m: {value: 2, unit: kg}, d: {value: 3, unit: m}}
bodies: {A: {mass: m, position: x_A}}
connections: [{type: push, on: A, amount: d}]
)";
  try {
    (void)analyze_text(text, "t.yaml", rules);
    FAIL("expected an InputError");
  } catch (const InputError& e) {
    REQUIRE(e.diagnostics().size() == 1);
    CHECK(format(e.diagnostics()[0]) ==
          "t.yaml: equation 'LMB A (x)' is not dimensionally consistent: the term from push on A is a length (expected "
          "a force)");
  }
}

TEST_CASE("Simplest: a product known by its parts gives the form simplest() gives the whole", "[solve]") {
  using namespace GiNaC;
  const symbol a("a"), g("g"), k("k"), m("m"), w("w");
  // The cord's amplitude condition: -m^2 (a k w^2 + g k - g m w^2)(a k w^2 + g m w^2 - g k).
  const ex p1 = a * k * pow(w, 2) + g * k - g * m * pow(w, 2), p2 = a * k * pow(w, 2) + g * m * pow(w, 2) - g * k;
  const ex whole = (-pow(m, 2) * p1 * p2).expand();
  const ex by_parts = simplest_of_product(whole, {(m * p1).expand(), (m * p2).expand()});
  CHECK(by_parts.is_equal(simplest(whole)));
  CHECK(to_text(by_parts) == "-m^2*(a*k*w^2 + g*k - g*m*w^2)*(a*k*w^2 + g*m*w^2 - g*k)");
  // Parts that are not the whole's factors: the whole is simplified as it is.
  CHECK(simplest_of_product(whole, {p1, p1}).is_equal(simplest(whole)));
}

TEST_CASE("Simplest: a compound Atwood machine's sums over all masses but one are divided through", "[solve]") {
  using namespace GiNaC;
  // Ten levels: the denominator is sum_k 4^(k-1) prod_{j != k} m_j. Divided by the product of
  // all ten masses (by hand), a tension 2 g prod_j m_j / den is 2 g / (sum_k 4^(k-1)/m_k).
  const possymbol g("g");
  std::vector<possymbol> m;
  for (int k = 1; k <= 10; ++k) m.emplace_back("m_" + std::to_string(k));
  ex all = 1, den = 0, reciprocal_sum = 0;
  for (const auto& x : m) all *= x;
  for (int k = 0; k < 10; ++k) {
    const ex c = pow(4, k);
    den += c * all / m[static_cast<std::size_t>(k)];
    reciprocal_sum += c / m[static_cast<std::size_t>(k)];
  }
  const ex tension = 2 * g * all / den.expand();
  const ex expected = 2 * g / reciprocal_sum;
  const ex s = simplest(tension);
  CHECK(normal(s - tension).is_zero());
  CHECK(to_text(s) == to_text(expected));
  CHECK(to_text(s) ==
        "2*g/(1/m_1 + 4/m_2 + 16/m_3 + 64/m_4 + 256/m_5 + 1024/m_6 + 4096/m_7 + 16384/m_8 + 65536/m_9 + 262144/m_10)");
  // A chain's sum of 64 masses, each term one mass, is not that shape: kept as it is (tried
  // once, the inversion of all 64 masses took a minute).
  ex chain_sum = 0;
  std::vector<possymbol> many;
  for (int k = 1; k <= 64; ++k) many.emplace_back("m_" + std::to_string(k));
  for (const auto& x : many) chain_sum += x;
  const ex accel = g / chain_sum;
  CHECK(simplest(accel).is_equal(accel));
  // A small problem keeps its polynomial form: the Atwood machine.
  const possymbol m1("m_1"), m2("m_2"), m3("m_3");
  CHECK(to_text(simplest(g * (m1 - m2) / (m1 + m2))) == "g*(m_1 - m_2)/(m_1 + m_2)");
  CHECK(to_text(simplest(g * m1 * m2 / (m1 * m2 + 4 * m1 * m3 + m2 * m3))) ==
        "g*m_1*m_2/(m_1*m_2 + 4*m_1*m_3 + m_2*m_3)");
}
