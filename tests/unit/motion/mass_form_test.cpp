// The mass-matrix form M(q) q'' = F(q, q') of a chain of links (issue 42, item 7), against
// hand derivations: the double pendulum of two bobs on light rods, and of two uniform rods.
// Its linearisation about hanging straight down, M0 = M(0) and K0 = -dF/dq, and the
// frequencies of small oscillations, the classic (2 -+ sqrt(2)) g/l and (3 -+ 6/sqrt(7)) g/l.
#include <catch2/catch.hpp>

#include <cmath>

#include "motion/mass_form.hpp"
#include "motion/motion.hpp"
#include "../../support/helpers.hpp"

using namespace tackle;
using namespace tackle::test;
using namespace GiNaC;

namespace {

// Two links from the fixed pin P; each link's center in the angles above it (bench/links.py 2).
std::string chain(bool rods) {
  const std::string shape = rods ? ", shape: {rod: l}" : "";
  const std::string f = rods ? "l/2*" : "l*";
  return std::string(R"(title: two links
axes: [x, y]
parameters:
  m: {value: 3, unit: kg}
  l: {value: 2, unit: m}
  g: {value: 9.81, unit: m/s^2}
gravity: [0, -g]
bodies:
  link_1: {mass: m, angle: theta_1, center_of_mass: [")") +
         f + "sin(theta_1)\", \"-" + f + "cos(theta_1)\"]" + shape + R"(}
  link_2: {mass: m, angle: theta_2, center_of_mass: ["l*sin(theta_1) + )" +
         f + "sin(theta_2)\", \"-(l*cos(theta_1) + " + f + "cos(theta_2))\"]" + shape + R"(}
points:
  P: [0, 0]
  J_2: {on: link_1, offset: [0, )" +
         (rods ? "\"-l/2\"" : "0") + R"(]}
connections:
  - {type: pin, body: link_1, at: P}
  - {type: pin_joint, body: link_1, other: link_2, at: J_2}
motion:
  initial: {theta_1: 0.5, dot(theta_1): 0, theta_2: 0, dot(theta_2): 0}
  until: 1
)";
}

struct Hand {
  // M = m l^2 [[a, b c], [b c, d]], F = m l^2 [-b s w2^2, b s w1^2] - m g l [e sin1, f sin2],
  // c = cos(theta_1 - theta_2), s = sin(theta_1 - theta_2).
  double a, b, d, e, f;
};

void check_chain(bool rods, const Hand& h, double lambda_low, double lambda_high) {
  const auto an = run_text(chain(rods));
  REQUIRE(an);
  const Model& model = an->model;
  const SymbolTable& t = *model.symbols;
  std::string why;
  const auto form = mass_form(model, why);
  INFO(why);
  REQUIRE(form);
  CHECK(form->mass_varies);
  REQUIRE(form->M.rows() == 2);
  REQUIRE(form->F.size() == 2);
  const ex m = t.find("m")->sym, l = t.find("l")->sym, g = t.find("g")->sym;
  const ex q1 = t.find("theta_1")->sym, q2 = t.find("theta_2")->sym;
  const ex w1 = t.find("dot(theta_1)")->sym, w2 = t.find("dot(theta_2)")->sym;
  const double mv = 3, lv = 2, gv = 9.81;
  // At a few states, every entry against the hand values.
  for (const auto& [a1, a2, r1, r2] :
       {std::tuple{0.5, -0.3, 1.0, 2.0}, std::tuple{-1.2, 0.7, -0.4, 0.9}, std::tuple{2.0, 2.5, 0.0, -3.0}}) {
    INFO("theta_1 = " << a1 << ", theta_2 = " << a2);
    const exmap at{{q1, a1}, {q2, a2}, {w1, r1}, {w2, r2}};
    const double c = std::cos(a1 - a2), s = std::sin(a1 - a2), ml2 = mv * lv * lv, mgl = mv * gv * lv;
    CHECK(number(form->M(0, 0), t, at) == Approx(ml2 * h.a).epsilon(1e-12));
    CHECK(number(form->M(0, 1), t, at) == Approx(ml2 * h.b * c).epsilon(1e-12));
    CHECK(number(form->M(1, 0), t, at) == Approx(ml2 * h.b * c).epsilon(1e-12));
    CHECK(number(form->M(1, 1), t, at) == Approx(ml2 * h.d).epsilon(1e-12));
    CHECK(number(form->F[0], t, at) == Approx(-ml2 * h.b * s * r2 * r2 - mgl * h.e * std::sin(a1)).epsilon(1e-12));
    CHECK(number(form->F[1], t, at) == Approx(ml2 * h.b * s * r1 * r1 - mgl * h.f * std::sin(a2)).epsilon(1e-12));
  }
  // At rest: exactly M0 = m l^2 [[a, b], [b, d]], K0 = m g l diag(e, f), C0 = 0.
  const auto rest = at_rest(model, *form);
  REQUIRE(rest);
  auto exact = [](double x) { return numeric(static_cast<long>(std::lround(x * 12)), 12); };
  const matrix M0{2, 2,
                  lst{exact(h.a) * m * l * l, exact(h.b) * m * l * l, exact(h.b) * m * l * l, exact(h.d) * m * l * l}};
  const matrix K0{2, 2, lst{exact(h.e) * m * g * l, 0, 0, exact(h.f) * m * g * l}};
  for (unsigned i = 0; i < 2; ++i)
    for (unsigned j = 0; j < 2; ++j) {
      INFO("entry " << i << ", " << j << ": M0 " << rest->M0(i, j) << ", K0 " << rest->K0(i, j));
      CHECK(normal(rest->M0(i, j) - M0(i, j)).is_zero());
      CHECK(normal(rest->K0(i, j) - K0(i, j)).is_zero());
      CHECK(normal(rest->C0(i, j)).is_zero());
    }
  // The frequencies of small oscillations, from the motion (M0^-1 K0 per unit of inertia).
  REQUIRE(an->motion);
  REQUIRE(an->motion->eom.linearised);
  const auto& w = an->motion->eom.linearised->frequencies;
  REQUIRE(w.size() == 2);
  CHECK(w[0] == Approx(std::sqrt(lambda_low * gv / lv)).epsilon(1e-10));
  CHECK(w[1] == Approx(std::sqrt(lambda_high * gv / lv)).epsilon(1e-10));
}

}  // namespace

TEST_CASE("Mass-matrix form: two bobs on light rods, omega^2 = (2 -+ sqrt(2)) g/l", "[motion][mass_form]") {
  // Bob 1 at l (sin1, -cos1), bob 2 at l (sin1 + sin2, -cos1 - cos2): T = m l^2 (w1^2 + w2^2/2
  // + c w1 w2), V = -m g l (2 cos1 + cos2). M0^-1 K0 = (g/l) [[2, -1], [-2, 2]].
  check_chain(false, Hand{2, 1, 1, 2, 1}, 2 - std::sqrt(2.0), 2 + std::sqrt(2.0));
}

TEST_CASE("Mass-matrix form: two uniform rods, omega^2 = (3 -+ 6/sqrt(7)) g/l", "[motion][mass_form]") {
  // Rod 1's center at l/2 from P, rod 2's at l from P plus l/2, each m l^2/12 about its center:
  // M11 = m l^2 (1/4 + 1/12 + 1) = 4/3 m l^2, M12 = m l (l/2) c, M22 = m l^2 (1/4 + 1/12) = 1/3
  // m l^2; V = -m g l (3/2 cos1 + 1/2 cos2). det(K0 - lambda M0) = 0 with lambda in g/l:
  // 7 lambda^2 - 42 lambda + 27 = 0, lambda = 3 -+ 6/sqrt(7).
  check_chain(true, Hand{4.0 / 3, 0.5, 1.0 / 3, 1.5, 0.5}, 3 - 6 / std::sqrt(7.0), 3 + 6 / std::sqrt(7.0));
}
