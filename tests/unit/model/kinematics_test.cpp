// The kinematics home (model/kinematics.hpp) on a body that translates along x and turns by
// theta: each quantity against its textbook formula, written out by hand.
#include <catch2/catch.hpp>

#include "model/kinematics.hpp"

using namespace tackle;
using namespace GiNaC;

namespace {

struct Turning {
  symbol x{"x"}, xd{"dot(x)"}, xdd{"ddot(x)"}, th{"theta"}, thd{"dot(theta)"}, thdd{"ddot(theta)"};
  symbol M{"M"}, I{"I"}, r{"r"}, h{"h"};
  Model m;
  Turning() {
    m.axes = {"x", "y"};
    Body b;
    b.name = "wheel";
    b.mass = M;
    b.has_mass = true;
    b.cm = {x, 0, 0};
    b.has_cm = true;
    b.angle = th;
    b.inertia = I;
    m.bodies.push_back(b);
    m.coordinates.push_back({x, xd, xdd, 0, Coordinate::Kind::translation});
    m.coordinates.push_back({th, thd, thdd, 0, Coordinate::Kind::rotation});
  }
  const Body& body() const { return m.bodies[0]; }
};

bool same(const ex& a, const ex& b) { return normal(a - b).is_zero(); }

}  // namespace

TEST_CASE("Kinematics: a turning body's omega, alpha and the velocity of a point on its rim", "[kinematics]") {
  const Turning t;
  CHECK(same(kinematics::omega(t.m, t.body()), t.thd));
  CHECK(same(kinematics::alpha(t.m, t.body()), t.thdd));
  // v_P = v_G + omega x r_P/G with r_P/G = (r, 0): (dot(x), r dot(theta)).
  const auto v = kinematics::point_velocity(t.m, t.body(), {t.r, 0, 0});
  REQUIRE(v);
  CHECK(same((*v)[0], t.xd));
  CHECK(same((*v)[1], t.r * t.thd));
}

TEST_CASE("Kinematics: the rate of angular momentum about a point is r x m a + I alpha", "[kinematics]") {
  const Turning t;
  // About (0, h): r_G = (x, -h), m a = (M ddot(x), 0): r x m a = h M ddot(x) about z.
  const Vec h = kinematics::angular_momentum_rate(t.m, t.body(), {0, t.h, 0});
  CHECK(same(h[2], t.h * t.M * t.xdd + t.I * t.thdd));
  CHECK(same(h[0], 0));
  CHECK(same(h[1], 0));
}

TEST_CASE("Kinematics: kinetic energy, its rate and a load's power include the turning", "[kinematics]") {
  const Turning t;
  CHECK(same(kinematics::kinetic_energy(t.m, t.body(), [](const ex& e) { return e; }),
             t.M * pow(t.xd, 2) / 2 + t.I * pow(t.thd, 2) / 2));
  CHECK(same(kinematics::kinetic_energy_rate(t.m, t.body(), {t.xd, 0, 0}, t.thd),
             t.M * t.xd * t.xdd + t.I * t.thd * t.thdd));
  Load l;
  l.body = 0;
  const symbol F("F"), C("C");
  l.force = {F, 0, 0};
  l.couple = {0, 0, C};
  CHECK(same(kinematics::power(t.body(), l, {t.xd, 0, 0}, t.thd), F * t.xd + C * t.thd));
  // At the rim (r, 0) from the center, a vertical force P: P r dot(theta).
  Load rim;
  rim.body = 0;
  const symbol P("P");
  rim.force = {0, P, 0};
  rim.at = Vec{t.x + t.r, 0, 0};
  CHECK(same(kinematics::power(t.body(), rim, {t.xd, 0, 0}, t.thd), P * t.r * t.thd));
}

TEST_CASE("Kinematics: a body that only translates has no turning terms", "[kinematics]") {
  Turning t;
  t.m.bodies[0].angle = 0;
  t.m.bodies[0].inertia = 0;
  t.m.coordinates.pop_back();
  CHECK(kinematics::omega(t.m, t.body()).is_zero());
  CHECK(same(kinematics::kinetic_energy(t.m, t.body(), [](const ex& e) { return e; }), t.M * pow(t.xd, 2) / 2));
  CHECK(same(kinematics::momentum_rate(t.m, t.body())[0], t.M * t.xdd));
}

TEST_CASE("Kinematics: a body's translation coordinate and acceleration come from the model's coordinates",
          "[kinematics]") {
  const Turning t;
  const Coordinate* q = kinematics::translation(t.m, t.body());
  REQUIRE(q);
  CHECK(q->q.is_equal(t.x));
  CHECK(q->rate.is_equal(t.xd));
  CHECK(kinematics::acceleration_symbol(t.m, t.body()).is_equal(t.xdd));
  const Vec a = kinematics::acceleration(t.m, t.body());
  CHECK(same(a[0], t.xdd));
  CHECK(same(a[1], 0));
}

TEST_CASE("Kinematics: a pendulum's bob accelerates by L ddot(theta) along its path and L dot(theta)^2 to its pin",
          "[kinematics]") {
  const symbol th{"theta"}, thd{"dot(theta)"}, thdd{"ddot(theta)"}, L{"L"}, M{"M"};
  Model m;
  m.axes = {"x", "y"};
  Body bob;
  bob.name = "bob";
  bob.mass = M;
  bob.has_mass = true;
  bob.cm = {L * sin(th), -L * cos(th), 0};  // the pin at the origin, theta from the downward vertical
  bob.has_cm = true;
  bob.angle = th;
  m.bodies.push_back(bob);
  m.coordinates.push_back({th, thd, thdd, 0, Coordinate::Kind::rotation});
  CHECK(kinematics::translation(m, m.bodies[0]) == nullptr);
  CHECK(kinematics::acceleration_symbol(m, m.bodies[0]).is_zero());
  // By hand: tangential L ddot(theta) (cos, sin), normal L dot(theta)^2 (-sin, cos), towards the pin.
  const Vec a = kinematics::acceleration(m, m.bodies[0]);
  CHECK(same(a[0], L * thdd * cos(th) - L * pow(thd, 2) * sin(th)));
  CHECK(same(a[1], L * thdd * sin(th) + L * pow(thd, 2) * cos(th)));
  const Vec p = kinematics::momentum_rate(m, m.bodies[0]);
  CHECK(same(p[1], M * a[1]));
}

TEST_CASE("Kinematics: a body with no coordinate has its acceleration as given", "[kinematics]") {
  const symbol a{"a_B"}, g{"g"};
  Model m;
  m.axes = {"x", "y"};
  Body b;
  b.name = "B";
  b.mass = symbol("m");
  b.has_mass = true;
  b.along_unknown = a;
  b.given_acceleration = {a * 3 / 5, -a * 4 / 5, 0};  // along (3, -4), down a 3-4-5 slope
  m.bodies.push_back(b);
  CHECK(kinematics::translation(m, m.bodies[0]) == nullptr);
  CHECK(kinematics::acceleration_symbol(m, m.bodies[0]).is_equal(a));
  const Vec acc = kinematics::acceleration(m, m.bodies[0]);
  CHECK(same(acc[0], 3 * a / 5));
  CHECK(same(acc[1], -4 * a / 5));
  CHECK_FALSE(kinematics::velocity(m, m.bodies[0]));
}
