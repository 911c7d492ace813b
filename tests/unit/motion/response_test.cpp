// The closed-form response of one degree of freedom, against a hand derivation.
#include <catch2/catch.hpp>

#include "expr/parse.hpp"
#include "../../support/helpers.hpp"

using namespace tackle;
using namespace tackle::test;
using namespace GiNaC;

TEST_CASE("Response: a constant force given by a defined parameter is checked in the equation of motion", "[motion]") {
  // m x'' = F_0 - k x with F_0 = m g_0 defined: from rest at x = 0, x = F_0/k (1 - cos(lambda t)),
  // lambda = sqrt(k/m). The check puts the response back with F_0 replaced by its definition:
  // a residual left with F_0 in it cannot be evaluated, and then nothing would be checked.
  const auto a = run_text(R"(title: pushed block on a spring
axes: [x]
parameters:
  m: {value: 2, unit: kg}
  k: {value: 200, unit: N/m}
  g_0: {value: 5, unit: m/s^2}
  F_0: {define: m*g_0}
  L: {value: 0.5, unit: m}
bodies:
  block: {mass: m, position: x}
points:
  W: -L
connections:
  - {type: spring, name: sp, path: [W, block], k: k, rest_length: L}
loads:
  - {on: block, force: F_0}
layout: {x: 0}
given: [x]
find: [ddot(x)]
motion:
  initial: {x: 0, dot(x): 0}
)");
  REQUIRE(a->motion);
  REQUIRE(a->motion->response);
  const Response& r = *a->motion->response;
  CHECK(r.verified);
  const SymbolTable& table = *a->model.symbols;
  const auto want = parse_expression("F_0/k*(1 - cos(sqrt(k/m)*t))", table);
  REQUIRE(want.value);
  exmap defs = table.definitions();
  for (const auto& [sym, def] : a->motion->definitions) defs[sym] = def;
  ex difference = r.q - *want.value;
  for (int depth = 0; depth < 4; ++depth) difference = difference.subs(defs);
  CHECK(normal(difference).is_zero());
}
