// Phases, the end of an interval and impacts: each against a hand derivation.
#include <catch2/catch.hpp>

#include "expr/parse.hpp"
#include "expr/print.hpp"
#include "report/key.hpp"
#include "../../support/helpers.hpp"

using namespace tackle;
using namespace GiNaC;

namespace {

const Answer& answer(const Derivation& d, const std::string& name) {
  for (const auto& a : d.answers)
    if (a.name == name) return a;
  FAIL("no answer " << name);
  throw;
}

// Whether `got` equals `want` (text in the analysis' names), definitions put in.
bool same(const Analysis& a, const ex& got, const std::string& want) {
  const auto parsed = parse_expression(want, *a.model.symbols);
  REQUIRE(parsed.value);
  ex difference = got - *parsed.value;
  for (int depth = 0; depth < 8; ++depth) difference = difference.subs(a.model.symbols->definitions());
  return normal(difference).is_zero();
}

}  // namespace

TEST_CASE("Impact: a restitution of one half parts two blocks as momentum and restitution say", "[impact]") {
  // By hand: 2 kg at 5 m/s hits 3 kg at rest, e = 1/2. Momentum 10 = 2 a + 3 b, restitution
  // b - a = e (5 - 0) = 2.5: a = 0.5 m/s, b = 3 m/s. Impulses 3 (3 - 0) = 9 N s on B, -9 on A.
  // Kinetic energy 25 J before, 0.25 + 13.5 = 13.75 J after: 11.25 J lost, which is
  // (1 - e^2) m_A m_B (v_A - v_B)^2/(2 (m_A + m_B)) = 0.75*6*25/10.
  const auto a = test::run_text(R"(
title: two blocks collide
parameters:
  m_A: {value: 2, unit: kg}
  m_B: {value: 3, unit: kg}
  v_A: {value: 5, unit: m/s}
  e: {value: 0.5}
bodies:
  A: {mass: m_A, position: x_A}
  B: {mass: m_B, position: x_B}
impact:
  from: {dot(x_A): v_A, dot(x_B): 0}
  restitution: e
)");
  REQUIRE(a->impact);
  const Derivation d = explain(*a);
  CHECK(answer(d, "dot(x_A)").value->approx == Approx(0.5));
  CHECK(answer(d, "dot(x_B)").value->approx == Approx(3));
  CHECK(answer(d, "J_B").value->approx == Approx(9));
  CHECK(answer(d, "J_A").value->approx == Approx(-9));
  CHECK(answer(d, "E_lost").value->approx == Approx(11.25));
  CHECK(same(*a, *answer(d, "dot(x_A)").closed_form, "(m_A*v_A - m_B*e*v_A)/(m_A + m_B)"));
  CHECK(same(*a, *answer(d, "E_lost").closed_form, "(1 - e^2)*m_A*m_B*v_A^2/(2*(m_A + m_B))"));
  CHECK(d.power.status == PowerCheck::Status::not_applicable);
  const std::string text = write(d, Format::text, true);
  CHECK(text.find("    dot(x_B) - dot(x_A) = e*v_A    [restitution]") != std::string::npos);
  CHECK(text.find("With the given numbers the energy lost is not negative") != std::string::npos);
}

TEST_CASE("Interval: the rate at the end of a duration is v0 + a T, and the body moves v0 T + a T^2/2", "[interval]") {
  // By hand: F = 10 N on m = 2 kg, a = 5 m/s^2; from 1 m/s for 3 s: 16 m/s, 3 + 22.5 = 25.5 m.
  const auto a = test::run_text(R"(
title: a pushed block
parameters:
  m: {value: 2, unit: kg}
  F: {value: 10, unit: N}
  v_0: {value: 1, unit: m/s}
  T: {value: 3, unit: s}
bodies:
  A: {mass: m, position: x}
loads:
  - {on: A, force: F}
interval: {duration: T, from: {dot(x): v_0}}
find: [ddot(x)]
)");
  REQUIRE(a->interval_end);
  REQUIRE(a->interval_end->rates.size() == 1);
  const auto& r = a->interval_end->rates[0];
  CHECK(same(*a, r.value, "v_0 + F*T/m"));
  REQUIRE(r.displacement);
  CHECK(same(*a, *r.displacement, "v_0*T + F*T^2/(2*m)"));
  const Derivation d = explain(*a);
  CHECK(answer(d, "dot(x)").value->approx == Approx(16));
  CHECK(write(d, Format::text, true).find("= 25.5 m    [displacement over the interval]") != std::string::npos);
}

TEST_CASE("Interval: a body first moving away comes back through the distance with the distance's sign", "[interval]") {
  // By hand: from -2 m/s with a = +1 m/s^2 (F = 2 N, m = 2 kg) it turns and passes x = 6 m
  // with dot(x)^2 = 4 + 2*1*6 = 16: dot(x) = +4 m/s.
  const auto a = test::run_text(R"(
title: a block pushed back
parameters:
  m: {value: 2, unit: kg}
  F: {value: 2, unit: N}
  v_0: {value: -2, unit: m/s, positive: false}
  s: {value: 6, unit: m}
bodies:
  A: {mass: m, position: x}
loads:
  - {on: A, force: F}
interval: {distance: s, from: {dot(x): v_0}}
)");
  const Derivation d = explain(*a);
  CHECK(answer(d, "dot(x)").value->approx == Approx(4));
  CHECK(same(*a, *answer(d, "dot(x)").closed_form, "sqrt(v_0^2 + 2*F*s/m)"));
}

TEST_CASE("Phases: sample 12.5 carries v into the impact and V into the stop, and --phase picks one", "[phases]") {
  const auto a = analyze_file(TACKLE_SOURCE_DIR "/examples/sample-12.5-pile-driver.yaml", test::rules());
  REQUIRE(a->phases.size() == 3);
  REQUIRE(a->phases[0].carried.size() == 1);
  CHECK(a->phases[0].carried[0].first == "v");
  CHECK(same(*a->phases[0].analysis, a->phases[0].carried[0].second, "-sqrt(2*g*h)"));
  // In the stop, V is a defined parameter: V = M v/(m + M), v = -sqrt(2 g h).
  const Analysis& stop = *a->phases[2].analysis;
  const SymbolInfo* V = stop.model.symbols->find("V");
  REQUIRE(V);
  REQUIRE(V->definition);
  CHECK(same(stop, V->sym, "-M*sqrt(2*g*h)/(m + M)"));
  std::string problem;
  CHECK(pick_phase(*a, "stop", problem) == &stop);
  CHECK(pick_phase(*a, "", problem) == nullptr);
  CHECK(problem == "the description has phases (expected --phase with one of: fall, impact, stop)");
  problem.clear();
  CHECK(pick_phase(*a, "drop", problem) == nullptr);
  CHECK(problem == "there is no phase 'drop' (expected --phase with one of: fall, impact, stop)");
}

TEST_CASE("Phases: variants draw the shared parameters once for every phase", "[phases][key]") {
  // h drawn from [1, 3]; the stop's F_s must follow the same h as the fall: by hand F_s = (m +
  // M)(g + M^2 g h/((m + M)^2 s)) with m = 10, M = 50, g = 9.81, s = 0.05.
  const auto a = test::run_text(test::example_with("sample-12.5-pile-driver.yaml", "h: {value: 2, unit: m}",
                                                   "h: {value: 2, unit: m, range: [1, 3]}"));
  const auto ds = explain_phases(*a);
  std::vector<std::pair<const Model*, const Derivation*>> parts;
  for (std::size_t i = 0; i < ds.size(); ++i) parts.emplace_back(&a->phases[i].analysis->model, &ds[i]);
  const auto variants = draw_variants(parts, 4, 7, 6);
  REQUIRE(variants.size() == 3);
  for (std::size_t k = 0; k < 4; ++k) {
    const double h = variants[0][k].parameters.at(0).value;
    CHECK(variants[1][k].parameters.at(0).value == h);
    CHECK(variants[2][k].parameters.at(0).value == h);
    double F_s = 0;
    for (const auto& q : variants[2][k].answers)
      if (q.name == "F_s") F_s = q.value;
    CHECK(F_s == Approx(60 * (9.81 + 2500 * 9.81 * h / (3600 * 0.05))));
  }
}
