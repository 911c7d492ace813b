// Bodies that turn in the plane (issue 31): an angle coordinate, the moment of inertia from a
// shape, points that turn with the body, the balances with I alpha, the power check. Expected
// values by hand (see each example's notes).
#include <catch2/catch.hpp>

#include <cmath>

#include "motion/simulate.hpp"
#include "../../support/helpers.hpp"

using namespace tackle;
using namespace tackle::test;
using namespace GiNaC;

namespace {

bool same(const ex& a, const ex& b) { return normal(a - b).is_zero(); }

ex sym(const Analysis& a, const std::string& name) { return a.model.symbols->find(name)->sym; }

}  // namespace

TEST_CASE("Rotation: a bar pinned at its end, AMB about the pin reads m L^2/3 ddot(theta)", "[rotation]") {
  // By hand: about O, r_G x m a_G = m L^2/4 ddot(theta) and I_G alpha = m L^2/12 ddot(theta);
  // gravity's moment -(L/2) m g cos(theta).
  const auto a = run_text(read_example("rotation-bar-released-from-horizontal.yaml") + "derive:\n  - {amb: bar, about: O}\n");
  REQUIRE(a->system.equations.size() == 1);
  const Equation& amb = a->system.equations[0];
  const ex m = sym(*a, "m"), L = sym(*a, "L"), g = sym(*a, "g"), th = sym(*a, "theta"), thdd = sym(*a, "ddot(theta)");
  CHECK(same(amb.rhs, m * pow(L, 2) * thdd / 3));
  CHECK(same(amb.lhs, -L * g * m * cos(th) / 2));
  CHECK(a->power.status == PowerCheck::Status::holds);
}

TEST_CASE("Rotation: a point on a turning body turns with it", "[rotation]") {
  // E at offset (L/2, 0) from G in the bar's frame is the bar's far end, (L cos, L sin).
  std::string text = read_example("rotation-bar-released-from-horizontal.yaml");
  text.replace(text.find("  O: [0, 0]"), 11, "  O: [0, 0]\n  E: {on: bar, offset: [\"L/2\", 0]}");
  const auto a = run_text(text);
  const auto e = std::find_if(a->model.points.begin(), a->model.points.end(), [](const Point& p) { return p.name == "E"; });
  REQUIRE(e != a->model.points.end());
  const ex L = sym(*a, "L"), th = sym(*a, "theta");
  CHECK(same(e->position[0], L * cos(th)));
  CHECK(same(e->position[1], L * sin(th)));
}

TEST_CASE("Rotation: moments of inertia from shapes, by the book's formulas", "[rotation]") {
  const std::string base = R"(title: shapes
axes: [x, y]
parameters:
  m: {value: 2, unit: kg}
  R: {value: 0.1, unit: m}
  a: {value: 0.3, unit: m}
bodies:
)";
  const std::vector<std::pair<std::string, std::string>> cases = {
      {"{disk: R}", "m*R^2/2"}, {"{ring: R}", "m*R^2"}, {"{rod: a}", "m*a^2/12"},
      {"{sphere: R}", "2*m*R^2/5"}, {"{box: [a, R]}", "m*(a^2 + R^2)/12"}, {"point", "0"}};
  for (const auto& [shape, formula] : cases) {
    const auto an = run_text(base + "  w: {mass: m, angle: phi, center_of_mass: [0, 0], shape: " + shape + "}\n");
    const auto expected = parse_expression(formula, *an->model.symbols);
    REQUIRE(expected.value);
    CHECK(same(an->model.bodies[0].inertia, *expected.value));
  }
  CHECK(errors_of(base + "  w: {mass: m, angle: phi, center_of_mass: [0, 0], shape: {cone: R}}\n") ==
        std::vector<std::string>{"t.yaml:8:60: unknown shape 'cone' of body 'w' (expected one of: point, disk, ring, rod, sphere, box)"});
  CHECK(errors_of(base + "  w: {mass: m, angle: phi, center_of_mass: [0, 0], shape: {box: [a]}}\n") ==
        std::vector<std::string>{"t.yaml:8:60: shape 'box' of body 'w' has 1 size (expected 2 lengths)"});
  CHECK(errors_of(base + "  w: {mass: m, angle: phi, center_of_mass: [0, 0], inertia: m*R, shape: point}\n") ==
        std::vector<std::string>{"t.yaml:8:61: body 'w' has both 'inertia' and 'shape' (the shape gives the moment of inertia; give one)"});
  CHECK(errors_of(base + "  w: {mass: m, angle: phi, center_of_mass: [0, 0], inertia: m*R}\n") ==
        std::vector<std::string>{"t.yaml:8:61: 'inertia' of body 'w' is a mass length (expected a moment of inertia)"});
}

TEST_CASE("Rotation: an angle is for 2-D problems and needs a center of mass", "[rotation][errors]") {
  CHECK(errors_of("title: t\naxes: [x]\nbodies:\n  A: {mass: 0, position: x, angle: phi}\n") ==
        std::vector<std::string>{"t.yaml:4:36: body 'A': 'angle' is for 2-D problems (a body turns in the plane)"});
  CHECK(errors_of("title: t\naxes: [x, y]\nbodies:\n  A: {mass: 0, angle: phi}\n") ==
        std::vector<std::string>{"t.yaml:4:23: body 'A' has an 'angle' but no 'center_of_mass' (expected its center of mass, "
                                 "fixed or written in its coordinates)"});
}

TEST_CASE("Rotation: a pendulum released from 60 deg swings with the elliptic-integral period", "[rotation][motion]") {
  // By hand: T = 4 K(k)/sqrt(g/l), k = sin(30 deg) = 1/2 (std::comp_ellint_1 is K), longer
  // than the small-angle 2 pi sqrt(l/g); the string stays taut (T >= m g cos(60 deg) > 0).
  const auto a = run_text(read_example("rotation-pendulum.yaml"));
  REQUIRE(a->motion);
  REQUIRE(a->motion->eom.linearised);
  SimulationSpec spec;
  spec.until = 2.5;
  spec.samples = 5001;
  spec.plot = {"theta"};
  const Simulation s = simulate(*a, spec, Location{});
  CHECK(s.complete);
  std::vector<double> crossings;
  const auto& t = s.table.x;
  const auto& th = s.table.y[0];
  for (std::size_t i = 1; i < t.size(); ++i)
    if (th[i - 1] && th[i] && (*th[i - 1] > 0) != (*th[i] > 0))
      crossings.push_back(t[i - 1] + (t[i] - t[i - 1]) * *th[i - 1] / (*th[i - 1] - *th[i]));
  REQUIRE(crossings.size() >= 2);
  const double period = 2 * (crossings[1] - crossings[0]);
  CHECK(period == Approx(4 * std::comp_ellint_1(0.5) / std::sqrt(9.81)).epsilon(1e-5));
  CHECK(period > 2 * M_PI / std::sqrt(9.81));
}

TEST_CASE("Rotation: an initial angle may be given with its unit", "[rotation][motion]") {
  std::string text = read_example("rotation-pendulum.yaml");
  text.replace(text.find("initial: {theta: pi/3, dot(theta): 0}"), 37,
               "initial: {theta: {value: 60, unit: deg}, dot(theta): {value: 0, unit: rpm}}");
  const auto a = run_text(text);
  REQUIRE(a->model.motion);
  CHECK(same(a->model.motion->initial.at(sym(*a, "theta")), Pi / 3));
  std::string wrong = text;
  wrong.replace(wrong.find("{value: 60, unit: deg}"), 22, "{value: 60, unit: m}");
  CHECK(errors_of(wrong) == std::vector<std::string>{"t.yaml:33:38: initial value of 'theta' is a pure number, but m is a length"});
}
