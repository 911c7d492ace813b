// Each bundled support rule on a small statics problem whose answer is plain by hand.
#include <catch2/catch.hpp>

#include "expr/print.hpp"
#include "../../support/helpers.hpp"

using namespace tackle;

namespace {
std::map<std::string, std::string> answers(const std::string& yaml) {
  const auto a = test::run_text(yaml);
  REQUIRE(a->solution.status == Solution::Status::determined);
  std::map<std::string, std::string> out;
  for (const auto& d : a->solution.values) out[to_text(d.unknown)] = to_text(d.value);
  return out;
}
const std::string beam2d = R"(title: beam
axes: [x, y]
parameters: {m: {unit: kg}, g: {unit: m/s^2}, L: {unit: m}}
gravity: [0, -g]
points: {A: [0, 0], B: [L, 0]}
bodies: {beam: {mass: m, center_of_mass: [L/2, 0]}}
)";
}  // namespace

TEST_CASE("Rules: pin and roller hold a beam up with half its weight each", "[rules][statics]") {
  const auto r = answers(beam2d + R"(connections:
  - {type: pin, body: beam, at: A}
  - {type: roller, body: beam, at: B, normal: [0, 1]}
)");
  CHECK(r == std::map<std::string, std::string>{{"A_x", "0"}, {"A_y", "g*m/2"}, {"N_B", "g*m/2"}});
}

TEST_CASE("Rules: a 2-D fixed support carries the weight and its moment", "[rules][statics]") {
  const auto r = answers(beam2d + "connections: [{type: fixed_support, body: beam, at: A}]\n");
  CHECK(r == std::map<std::string, std::string>{{"A_x", "0"}, {"A_y", "g*m"}, {"M_A", "L*g*m/2"}});
}

TEST_CASE("Rules: a couple on a pinned beam is balanced by a cable", "[rules][statics]") {
  const auto r = answers(test::pinned_beam_with_couple);
  CHECK(r == std::map<std::string, std::string>{{"A_x", "0"}, {"A_y", "M/L"}, {"T_BC", "-M/L"}});
}

TEST_CASE("Rules: a sticking block pushed sideways holds by friction", "[rules][statics]") {
  const auto a = test::run_text(R"(title: sticking
axes: [x, y]
parameters: {m: {value: 2, unit: kg}, g: {value: 10, unit: m/s^2}, P: {value: 5, unit: N}, mu: {value: 0.2, positive: true}}
gravity: [0, -g]
points: {A: [0, 0]}
bodies: {block: {mass: m, center_of_mass: [0, 0]}}
loads: [{on: block, at: A, force: [P, 0]}]
connections: [{type: sticking, body: block, at: A, normal: [0, 1], tangent: [1, 0], mu: mu}]
derive: [{lmb: block}]
)");
  const Derivation d = explain(*a);
  std::map<std::string, std::string> r;
  for (const auto& ans : d.answers) r[ans.name] = to_text(*ans.closed_form);
  CHECK(r == std::map<std::string, std::string>{{"N_A", "g*m"}, {"F_A", "-P"}});
  REQUIRE(d.conditions.size() == 3);
  CHECK(*d.conditions[0].holds);        // N >= 0
  CHECK(*d.conditions[1].holds);        // F <= mu N: -5 <= 4
  CHECK_FALSE(*d.conditions[2].holds);  // -F <= mu N: 5 <= 4 fails: it slips
  CHECK(d.conditions[2].otherwise == "the contact slips");
}

TEST_CASE("Rules: a rear-wheel-drive car's traction is m a, and mu is checked only when given", "[rules][statics]") {
  const std::string car = R"(title: drive
axes: [x, y]
parameters: {m: {unit: kg}, g: {unit: m/s^2}, a: {unit: m/s^2}, c: {unit: m}, d: {unit: m}, h: {unit: m}}
gravity: [0, -g]
points: {R: [-c, 0], F: [d, 0]}
bodies: {car: {mass: m, center_of_mass: [0, h], acceleration: [a, 0]}}
connections:
  - {type: free_wheel, body: car, at: F, normal: [0, 1]}
)";
  const auto r = answers(car + "  - {type: driven_wheel, body: car, at: R, normal: [0, 1], rolling: [1, 0]}\n");
  CHECK(r.at("F_R") == "a*m");
  CHECK(r.at("N_R") == "m*(a*h + d*g)/(c + d)");
  CHECK(r.at("N_F") == "m*(c*g - a*h)/(c + d)");
  const auto without_mu =
      explain(*test::run_text(car + "  - {type: driven_wheel, body: car, at: R, normal: [0, 1], rolling: [1, 0]}\n"));
  const auto with_mu = explain(
      *test::run_text(car + "  - {type: driven_wheel, body: car, at: R, normal: [0, 1], rolling: [1, 0], mu: 1}\n"));
  CHECK(with_mu.conditions.size() == without_mu.conditions.size() + 2);
}

TEST_CASE("Rules: a 3-D weld and a hinge with moment reactions carry a cantilever", "[rules][statics]") {
  const std::string head = R"(title: cantilever
axes: [x, y, z]
parameters: {m: {unit: kg}, g: {unit: m/s^2}, L: {unit: m}}
gravity: [0, 0, -g]
points: {O: [0, 0, 0]}
bodies: {beam: {mass: m, center_of_mass: [L, 0, 0]}}
)";
  const auto w = answers(head + "connections: [{type: weld, body: beam, at: O}]\n");
  CHECK(w == std::map<std::string, std::string>{
                 {"O_x", "0"}, {"O_y", "0"}, {"O_z", "g*m"}, {"M_Ox", "0"}, {"M_Oy", "-L*g*m"}, {"M_Oz", "0"}});
  // A hinge along z resists turning about x and y only; the weight has no moment about z.
  const auto h = answers(head + "connections: [{type: hinge_with_moments, body: beam, at: O, axis: [0, 0, 1]}]\n");
  CHECK(h.at("O_z") == "g*m");
  CHECK(h.at("M_O1") + " " + h.at("M_O2") != "0 0");
}
