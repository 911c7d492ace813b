// A load's origin as data: its sentence, its key and its phrase, made from the data.
#include <catch2/catch.hpp>

#include "equations/equations.hpp"
#include "model/forces.hpp"
#include "../../support/helpers.hpp"

using namespace tackle;

namespace {

// Block A slides on a rough floor, pushed by a force at its center and tied by string s over
// pulley P to the hanging block B.
const std::string pulled_block = R"(title: "a block sliding on a rough floor, tied over a pulley to a hanging block"
axes: [x, y]
parameters:
  m_A: {value: 4, unit: kg}
  m_B: {value: 6, unit: kg}
  g: {value: 9.81, unit: m/s^2}
  mu: {value: 0.2}
  F: {value: 10, unit: N}
  L: {value: 2, unit: m}
gravity: [0, -g]
bodies:
  A: {mass: m_A, position: x, center_of_mass: [x, 0]}
  B: {mass: m_B, position: y, center_of_mass: [L, y]}
points:
  P: [L, 0]
connections:
  - {type: sliding, body: A, at: A, normal: [0, 1], sliding: [1, 0], mu: mu}
  - {type: force, on: A, at: A, force: [-F, 0]}
  - {type: pulley, at: P}
strings:
  - {name: s, path: [A, P, B], tension: T}
layout: {x: -1, y: -1}
find: [ddot(x)]
)";

// The origin of the first load on body `body` of kind `kind`.
const LoadOrigin& origin_of(const Model& m, const std::string& body, LoadOrigin::Kind kind) {
  for (const Load& l : m.loads)
    if (l.origin.kind == kind && m.bodies[static_cast<std::size_t>(l.body)].name == body) return l.origin;
  throw std::logic_error("no such load on " + body);
}

}  // namespace

TEST_CASE("Load origin: a strand's, a weight's, an applied force's and a sliding contact's", "[model][load]") {
  const auto a = test::run_text(pulled_block);
  const Model& m = a->model;
  using Kind = LoadOrigin::Kind;

  const LoadOrigin& strand = origin_of(m, "A", Kind::strand);
  CHECK(sentence(strand) == "string s: strand A-P at A");
  CHECK(force_key(strand) == "string s: strand A-P");
  CHECK(force_phrase(strand) == "a strand of string s at A");
  const LoadOrigin& other_end = origin_of(m, "B", Kind::strand);
  CHECK(sentence(other_end) == "string s: strand P-B at B");
  CHECK(force_key(other_end) == "string s: strand P-B");

  const LoadOrigin& weight = origin_of(m, "B", Kind::weight);
  CHECK(sentence(weight) == "gravity on B");
  CHECK(force_key(weight) == "gravity on B");
  CHECK(force_phrase(weight) == "the weight of B");

  const LoadOrigin& applied = origin_of(m, "A", Kind::applied);
  CHECK(sentence(applied) == "force at A");
  CHECK(force_key(applied) == "force at A");
  CHECK(force_phrase(applied) == "the force at A");

  const LoadOrigin& sliding = origin_of(m, "A", Kind::sliding);
  CHECK(sentence(sliding) == "sliding at A");
  CHECK(force_key(sliding) == "sliding at A");
  CHECK(force_phrase(sliding) == "the force of the sliding contact at A");
  CHECK(couple_phrase(sliding) == "the couple of the sliding at A");

  // Each load's printed source is its origin's sentence; a balance's terms carry the origins.
  for (const Load& l : m.loads) CHECK(l.source() == sentence(l.origin));
  const EquationSystem s = build_equations(m);
  for (const Equation& e : s.equations) {
    if (e.kind != Equation::Kind::lmb) continue;
    REQUIRE(e.origins.size() == e.sources.size());
    for (std::size_t j = 0; j < e.sources.size(); ++j) CHECK(e.sources[j] == sentence(e.origins[j]));
  }
}

TEST_CASE("Load origin: a connection's length sum keeps its body in its key, and a couple's phrase is its own",
          "[model][load]") {
  const LoadOrigin string = connection_origin("string s", "string");
  const LoadOrigin on_a = length_sum_origin(string, "A");
  CHECK(sentence(on_a) == "string s (from its length sum) on A");
  CHECK(force_key(on_a) == "string s (from its length sum) on A");
  CHECK(force_phrase(on_a) == "the force of the string s (from its length sum) on A");
  const LoadOrigin couple = connection_origin("couple on beam", "couple");
  CHECK(sentence(couple) == "couple on beam");
  CHECK(force_phrase(couple) == "the force of the couple on beam");
  CHECK(couple_phrase(couple) == "the couple on beam");
  const LoadOrigin cable = strand_origin(connection_origin("cable from B", "cable"), "B-C", "B");
  CHECK(sentence(cable) == "cable from B: strand B-C at B");
  CHECK(force_phrase(cable) == "the force of cable from B at B");
}
