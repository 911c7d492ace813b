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
  const auto a =
      run_text(read_example("rotation-bar-released-from-horizontal.yaml") + "derive:\n  - {amb: bar, about: O}\n");
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
  const auto e =
      std::find_if(a->model.points.begin(), a->model.points.end(), [](const Point& p) { return p.name == "E"; });
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
  const std::vector<std::pair<std::string, std::string>> cases = {{"{disk: R}", "m*R^2/2"},
                                                                  {"{ring: R}", "m*R^2"},
                                                                  {"{rod: a}", "m*a^2/12"},
                                                                  {"{sphere: R}", "2*m*R^2/5"},
                                                                  {"{box: [a, R]}", "m*(a^2 + R^2)/12"},
                                                                  {"point", "0"}};
  for (const auto& [shape, formula] : cases) {
    const auto an = run_text(base + "  w: {mass: m, angle: phi, center_of_mass: [0, 0], shape: " + shape + "}\n");
    const auto expected = parse_expression(formula, *an->model.symbols);
    REQUIRE(expected.value);
    CHECK(same(an->model.bodies[0].inertia, *expected.value));
  }
  CHECK(errors_of(base + "  w: {mass: m, angle: phi, center_of_mass: [0, 0], shape: {cone: R}}\n") ==
        std::vector<std::string>{
            "t.yaml:8:60: unknown shape 'cone' of body 'w' (expected one of: point, disk, ring, rod, sphere, box)"});
  CHECK(errors_of(base + "  w: {mass: m, angle: phi, center_of_mass: [0, 0], shape: {box: [a]}}\n") ==
        std::vector<std::string>{"t.yaml:8:60: shape 'box' of body 'w' has 1 size (expected 2 lengths)"});
  CHECK(errors_of(base + "  w: {mass: m, angle: phi, center_of_mass: [0, 0], inertia: m*R, shape: point}\n") ==
        std::vector<std::string>{
            "t.yaml:8:61: body 'w' has both 'inertia' and 'shape' (the shape gives the moment of inertia; give one)"});
  CHECK(errors_of(base + "  w: {mass: m, angle: phi, center_of_mass: [0, 0], inertia: m*R}\n") ==
        std::vector<std::string>{"t.yaml:8:61: 'inertia' of body 'w' is a mass length (expected a moment of inertia)"});
}

TEST_CASE("Rotation: an angle is for 2-D problems and needs a center of mass", "[rotation][errors]") {
  CHECK(errors_of("title: t\naxes: [x]\nbodies:\n  A: {mass: 0, position: x, angle: phi}\n") ==
        std::vector<std::string>{"t.yaml:4:36: body 'A': 'angle' is for 2-D problems (a body turns in the plane)"});
  CHECK(errors_of("title: t\naxes: [x, y]\nbodies:\n  A: {mass: 0, angle: phi}\n") ==
        std::vector<std::string>{
            "t.yaml:4:23: body 'A' has an 'angle' but no 'center_of_mass' (expected its center of mass, "
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
  CHECK(errors_of(wrong) ==
        std::vector<std::string>{"t.yaml:33:38: initial value of 'theta' is a pure number, but m is a length"});
}

TEST_CASE("Rotation: a string that grips a pulley winds on by R dphi, and each side pulls with its own tension",
          "[rotation][string]") {
  // By hand (the example's notes): y_1 + R phi and y_2 - R phi are constant; AMB of the disk
  // R T_1 - R T_2 = (M R^2/2) ddot(phi).
  const auto a = run_text(read_example("rotation-atwood-massive-pulley.yaml"));
  const ex R = sym(*a, "R"), M = sym(*a, "M"), phi = sym(*a, "phi"), y1 = sym(*a, "y_1"), y2 = sym(*a, "y_2");
  const ex T1 = sym(*a, "T_1"), T2 = sym(*a, "T_2"), phidd = sym(*a, "ddot(phi)");
  REQUIRE(a->model.constraints.size() == 2);
  CHECK(same(a->model.constraints[0].quantity, -y1 - R * phi));
  CHECK(same(a->model.constraints[1].quantity, -y2 + R * phi));
  bool amb = false;
  for (const Equation& e : a->system.equations)
    if (e.label == "AMB P about its center of mass (z)") {
      amb = true;
      CHECK(same(e.lhs - e.rhs, R * T1 - R * T2 - M * pow(R, 2) * phidd / 2));
    }
  CHECK(amb);
  CHECK(a->power.status == PowerCheck::Status::holds);
}

TEST_CASE("Rotation: a strand that does not leave the rim along a tangent is refused", "[rotation][string][errors]") {
  std::string text = read_example("rotation-atwood-massive-pulley.yaml");
  // E at the bottom of the disk, with block 2 straight below it: the strand meets the rim
  // along the radius.
  text.replace(text.find("E: {on: P, offset: [R, 0]"), 25, "E: {on: P, offset: [0, \"-R\"]");
  text.replace(text.find("center_of_mass: [R, y_2]"), 24, "center_of_mass: [0, y_2]");
  CHECK(errors_of(text) ==
        std::vector<std::string>{
            "t.yaml:35:5: the strand block_2-E of string s_2 does not leave body 'P' along a tangent at 'E' (a "
            "string winds on a turning body where it leaves the rim at right angles to the radius; expected "
            "the strand at right angles to the offset 0, -R)"});
}

TEST_CASE("Rotation: 'turns: false' is for a point of a body that turns", "[rotation][errors]") {
  CHECK(errors_of("title: t\naxes: [x, y]\nbodies:\n  A: {mass: 0, position: x, center_of_mass: [x, 0]}\npoints:\n"
                  "  C: {on: A, offset: [0, 1], turns: false}\n") ==
        std::vector<std::string>{
            "t.yaml:6:37: point 'C' has 'turns: false', but body 'A' does not turn (expected a body with an 'angle')"});
  CHECK(
      errors_of("title: t\naxes: [x, y]\nbodies:\n  A: {mass: 0, position: x, center_of_mass: [x, 0]}\npoints:\n"
                "  C: {at: [0, 1], turns: no}\n") ==
      std::vector<std::string>{"t.yaml:6:26: 'turns' of point 'C' is 'no' (expected true or false)",
                               "t.yaml:6:26: 'turns' of point 'C' needs 'on' (only a point on a body turns with it)"});
}

TEST_CASE("Rotation: a cylinder rolls down an incline with a = 2/3 g sin(theta), tied by x + r phi",
          "[rotation][rolling]") {
  const auto a = run_text(read_example("rotation-cylinder-rolling-down-incline.yaml"));
  const ex r = sym(*a, "r"), s = sym(*a, "s"), phi = sym(*a, "phi");
  REQUIRE(a->model.constraints.size() == 1);
  CHECK(same(a->model.constraints[0].quantity, -s - r * phi));
  CHECK(a->power.status == PowerCheck::Status::holds);
}

TEST_CASE("Rotation: rolling needs a turning body and a contact point that keeps the ground's directions",
          "[rotation][rolling][errors]") {
  std::string text = read_example("rotation-cylinder-rolling-down-incline.yaml");
  std::string turning = text;
  turning.replace(turning.find(", turns: false}"), 15, "}");
  CHECK(errors_of(turning) ==
        std::vector<std::string>{
            "t.yaml:37:5: the contact point 'C' of a 'rolling' connection is not a point of body 'cylinder' "
            "that keeps the ground's directions (expected a point written {on: cylinder, offset: ..., turns: "
            "false}, where the wheel touches the surface)"});
  std::string aside = text;
  const std::string below = "offset: [\"-r*sin(theta)\", \"-r*cos(theta)\"]";
  aside.replace(aside.find(below), below.size(), "offset: [\"-r*cos(theta)\", \"r*sin(theta)\"]");
  CHECK(errors_of(aside) ==
        std::vector<std::string>{
            "t.yaml:37:5: the contact point 'C' of a 'rolling' connection is not straight across the surface "
            "from the center of body 'cylinder' (expected its offset -r*cos(theta), r*sin(theta) at right "
            "angles to the rolling direction)"});
}

TEST_CASE("String: a length sum in a 2-D problem pulls along each coordinate's line (the Atwood machine)", "[string]") {
  // By hand: as the 1-D Atwood machine, ddot(y_A) = (m_B - m_A) g/(m_A + m_B), T = 2 m_A m_B g/(m_A + m_B).
  const auto a = run_text(R"(title: t
axes: [x, y]
parameters:
  m_A: {value: 3, unit: kg}
  m_B: {value: 5, unit: kg}
  g: {value: 9.81, unit: m/s^2}
gravity: [0, -g]
bodies:
  A: {mass: m_A, position: y_A, center_of_mass: [0, y_A]}
  B: {mass: m_B, position: y_B, center_of_mass: [1, y_B]}
strings:
  - {name: s, length: "-y_A - y_B", tension: T}
find: [ddot(y_A), T]
)");
  const ex mA = sym(*a, "m_A"), mB = sym(*a, "m_B"), g = sym(*a, "g");
  CHECK(same(*a->solution.value_of(sym(*a, "ddot(y_A)")), (mB - mA) * g / (mA + mB)));
  CHECK(same(*a->solution.value_of(sym(*a, "T")), 2 * mA * mB * g / (mA + mB)));
}

TEST_CASE("Rotation: a ball thrown without spin slides until its contact stops slipping, at t = 2 v_0/(7 mu g)",
          "[rotation][motion]") {
  const auto a = run_text(read_example("rotation-ball-slides-then-rolls.yaml"));
  SimulationSpec spec;
  spec.until = 2;
  spec.plot = {"dot(x)"};
  const Simulation run = simulate(*a, spec, Location{});
  const double t1 = 2 * 8 / (7 * 0.2 * 9.81);
  CHECK_FALSE(run.complete);
  REQUIRE(run.events.size() == 1);
  CHECK(run.events[0].t == Approx(t1).epsilon(1e-9));
  CHECK(run.events[0].what ==
        "sliding at C: the contact stops slipping (its friction would change; the body may roll from here)");
  REQUIRE(run.table.y[0].back());
  CHECK(*run.table.y[0].back() == Approx(5.0 * 8 / 7).epsilon(1e-9));  // it rolls on at 5 v_0/7
}

TEST_CASE("Rotation: with backspin the ball stops and comes back while its contact still slides forwards",
          "[rotation][motion]") {
  // v_0 = 2 m/s, R omega_0 = 10 m/s of backspin: dot(x) = v_0 - mu g t turns at t = 1.019 s,
  // but the contact slides forwards, at v_0 + R omega_0 - (7/2) mu g t, until t = 2 (v_0 +
  // R omega_0)/(7 mu g) = 1.7474 s: the friction keeps its direction until then.
  std::string text = read_example("rotation-ball-slides-then-rolls.yaml");
  const std::string start = "initial: {x: 0, dot(x): 8, phi: 0, dot(phi): 0}";
  text.replace(text.find(start), start.size(),
               "initial: {x: 0, dot(x): 2, phi: 0, dot(phi): {value: 90.909090909090909, unit: rad/s}}");
  const auto a = run_text(text);
  SimulationSpec spec;
  spec.until = 3;
  const Simulation run = simulate(*a, spec, Location{});
  REQUIRE(run.events.size() == 1);
  CHECK(run.events[0].t == Approx(2 * 12 / (7 * 0.2 * 9.81)).epsilon(1e-9));
}

TEST_CASE("Rotation: a car on a banked curve keeps its line between two speeds, solved for v^2",
          "[rotation][validity]") {
  // By hand (the example's notes): v^2 <= g r (sin + mu cos)/(cos - mu sin), while cos > mu
  // sin; v^2 >= g r (sin - mu cos)/(cos + mu sin).
  const auto a = run_text(read_example("rotation-car-on-banked-curve.yaml"));
  const ex g = sym(*a, "g"), r = sym(*a, "r"), mu = sym(*a, "mu"), v = sym(*a, "v"), b = sym(*a, "beta");
  std::vector<std::pair<std::string, ex>> found;
  for (const auto& c : a->solution.conditions)
    for (const auto& sv : c.solved)
      if (sv.parameter.is_equal(pow(v, 2))) found.emplace_back(sv.op, sv.bound);
  REQUIRE(found.size() == 2);
  CHECK(found[0].first == "<=");
  CHECK(same(found[0].second, g * r * (sin(b) + mu * cos(b)) / (cos(b) - mu * sin(b))));
  CHECK(found[1].first == ">=");
  CHECK(same(found[1].second, g * r * (sin(b) - mu * cos(b)) / (cos(b) + mu * sin(b))));
}

TEST_CASE("Rotation: the rolling condition is solved for mu where the incline's angle is acute",
          "[rotation][validity]") {
  const auto a = run_text(read_example("rotation-cylinder-rolling-down-incline.yaml"));
  const ex mu = sym(*a, "mu"), th = sym(*a, "theta");
  bool found = false;
  for (const auto& c : a->solution.conditions)
    for (const auto& sv : c.solved)
      if (sv.parameter.is_equal(mu) && sv.op == ">=" && same(sv.bound, sin(th) / (3 * cos(th)))) found = true;
  CHECK(found);
}

TEST_CASE("Rotation: a bob written in its cart's coordinate accelerates with the cart (chain rule on every coordinate)",
          "[rotation]") {
  // The bob at (x + l sin(theta), -l cos(theta)): its LMB in x carries m ddot(x) too. (It did
  // not: only the body's own coordinates were differentiated, and the pendulum on a cart
  // swung as if its pin were fixed.)
  const auto a = run_text(read_example("rotation-pendulum-on-a-cart.yaml"));
  const ex m = sym(*a, "m"), l = sym(*a, "l"), x_dd = sym(*a, "ddot(x)"), th = sym(*a, "theta"),
           th_d = sym(*a, "dot(theta)"), th_dd = sym(*a, "ddot(theta)");
  bool found = false;
  for (const Equation& e : a->system.equations)
    if (e.label == "LMB bob (x)") {
      found = true;
      CHECK(same(e.rhs, m * x_dd + m * l * cos(th) * th_dd - m * l * sin(th) * pow(th_d, 2)));
    }
  CHECK(found);
  // The pin joint adds no constraint: the coordinates keep the pin on both bodies.
  CHECK(a->model.constraints.empty());
}
