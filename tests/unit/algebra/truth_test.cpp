// The verdict algebra (src/algebra/): exact angles, linear algebra at a point, and whether an
// equation holds on a family's solutions. Every value below is worked out by hand.
#include <catch2/catch.hpp>

#include <cmath>

#include "algebra/program.hpp"
#include "algebra/states.hpp"
#include "algebra/truth.hpp"

using namespace tackle;
using namespace GiNaC;

namespace {

const symbol theta("theta"), phi("phi"), a("a"), x("x"), y("y");

numeric at(const ex& e, const Sample& p, const std::vector<bool>& angles) {
  const auto v = Program(e, p, {}, angles)(p);
  REQUIRE(v);
  return *v;
}

}  // namespace

TEST_CASE("Program: an angle at t = tan(angle/2) has an exact sine and cosine, and so do its whole multiples",
          "[algebra]") {
  // t = 1/2: cos = (1 - 1/4)/(1 + 1/4) = 3/5, sin = 1/(5/4) = 4/5. phi at t = 1/3: cos =
  // (8/9)/(10/9) = 4/5, sin = (2/3)/(10/9) = 3/5.
  const Sample p{{theta, numeric(1, 2)}, {phi, numeric(1, 3)}};
  const std::vector<bool> angles{true, true};
  CHECK(at(cos(theta), p, angles) == numeric(3, 5));
  CHECK(at(sin(theta), p, angles) == numeric(4, 5));
  CHECK(at(tan(theta), p, angles) == numeric(4, 3));
  CHECK(at(sin(-theta), p, angles) == numeric(-4, 5));
  // sin 2x = 2 sin cos = 24/25, cos 2x = cos^2 - sin^2 = -7/25.
  CHECK(at(sin(2 * theta), p, angles) == numeric(24, 25));
  CHECK(at(cos(2 * theta), p, angles) == numeric(-7, 25));
  // cos(x + pi/2) = -sin x; sin(x - pi/2) = -cos x; cos(x + pi) = -cos x.
  CHECK(at(cos(theta + Pi / 2), p, angles) == numeric(-4, 5));
  CHECK(at(sin(theta - Pi / 2), p, angles) == numeric(-3, 5));
  CHECK(at(cos(theta + Pi), p, angles) == numeric(-3, 5));
  // sin(x - y) = sin x cos y - cos x sin y = 16/25 - 9/25.
  CHECK(at(sin(theta - phi), p, angles) == numeric(7, 25));
  // sin^2 + cos^2 = 1, exactly.
  CHECK(at(pow(sin(theta), 2) + pow(cos(theta), 2), p, angles) == 1);
  // The angle itself is 2 atan(1/2) = 0.927295218001612..., a float.
  const numeric alone = at(theta, p, angles);
  CHECK_FALSE(alone.is_rational());
  CHECK(alone.to_double() == Approx(0.9272952180016122));
  // Half an angle is no whole multiple: a float, sin(0.4636...) = 1/sqrt(5).
  CHECK(at(sin(theta / 2), p, angles).to_double() == Approx(1 / std::sqrt(5.0)));
  // An input that is not an angle: sin of its value, a float.
  CHECK(at(sin(theta), p, {false, false}).to_double() == Approx(std::sin(0.5)));
}

TEST_CASE("Program: the same values in doubles, a screen that says NaN where it cannot say", "[algebra]") {
  // The same angles as above (t = 1/2, t = 1/3), in doubles: cos = 0.6, sin(theta - phi) = 7/25,
  // cos(x + pi/2) = -0.8; a root: sqrt(x^2 + y^2 + a^2) at (2, 3, 6) is 7.
  const Sample p{{theta, numeric(1, 2)}, {phi, numeric(1, 3)}};
  const std::vector<bool> angles{true, true};
  const auto approx = [&](const ex& e) { return Program(e, p, {}, angles).approx(doubles_of(p)); };
  CHECK(approx(cos(theta)) == Approx(0.6));
  CHECK(approx(sin(theta - phi)) == Approx(0.28));
  CHECK(approx(cos(theta + Pi / 2)) == Approx(-0.8));
  CHECK(approx(theta) == Approx(0.9272952180016122));
  const Sample q{{x, numeric(2)}, {y, numeric(3)}, {a, numeric(6)}};
  CHECK(Program(sqrt(pow(x, 2) + pow(y, 2) + pow(a, 2)), q, {}).approx(doubles_of(q)) == Approx(7.0));
  CHECK(Program(exp(x) / y, q, {}).approx(doubles_of(q)) == Approx(std::exp(2.0) / 3));
  // 1/0, a symbol without a value, the log of a negative number: NaN, no screen.
  CHECK(std::isnan(Program(1 / (x - 2), q, {}).approx(doubles_of(q))));
  CHECK(std::isnan(Program(phi * x, q, {}).approx(doubles_of(q))));
  CHECK(std::isnan(Program(log(-x), q, {}).approx(doubles_of(q))));
}

TEST_CASE("Program: sin and cos swapped in doubles, as the swapped expression's value", "[algebra]") {
  // t = 1/2: sin = 0.8, cos = 0.6; phi: t = 1/3, sin = 0.6, cos = 0.8. Swapped: each sine a
  // cosine and each cosine a sine, of the same argument (whole multiples, an offset of pi/2, half
  // an angle alike); tan and everything else as they are.
  const Sample p{{theta, numeric(1, 2)}, {phi, numeric(1, 3)}};
  const std::vector<bool> angles{true, true};
  const auto swapped = [&](const ex& e) { return Program(e, p, {}, angles).approx(doubles_of(p), true); };
  CHECK(swapped(sin(theta)) == Approx(0.6));
  CHECK(swapped(cos(theta)) == Approx(0.8));
  CHECK(swapped(2 * sin(theta) + cos(phi)) == Approx(2 * 0.6 + 0.6));
  CHECK(swapped(sin(theta - phi)) == Approx(0.6 * 0.8 + 0.8 * 0.6));  // cos(theta - phi)
  CHECK(swapped(cos(theta + Pi / 2)) == Approx(0.6));                 // sin(theta + pi/2)
  CHECK(swapped(sin(theta / 2)) == Approx(2 / std::sqrt(5.0)));       // cos of half of it
  CHECK(swapped(tan(theta)) == Approx(0.8 / 0.6));
  CHECK(swapped(sin(cos(theta))) == Approx(std::cos(std::sin(2 * std::atan(0.5)))));
}

TEST_CASE("Linear algebra: a null space, a combination and a left inverse, exactly", "[algebra]") {
  const Tolerance tol{numeric(1, 1000000)};
  // x + 2y + 3z = 0: two free columns, (-2, 1, 0) and (-3, 0, 1).
  const auto n = null_space({{1, 2, 3}}, 3, tol);
  REQUIRE(n.size() == 2);
  CHECK(n[0] == Row{-2, 1, 0});
  CHECK(n[1] == Row{-3, 0, 1});
  // (3, 5) = 1 (1, 1) + 2 (1, 2); (1, 0) with (1, 1) and (2, 2): no combination.
  const auto c = combination_of({{1, 1}, {1, 2}}, {3, 5}, tol);
  REQUIRE(c);
  CHECK(*c == Row{1, 2});
  CHECK_FALSE(combination_of({{1, 1}, {2, 2}}, {1, 0}, tol));
  const auto inverse = left_inverse({{1, 1, 0}, {1, 2, 0}}, 3, tol);
  REQUIRE(inverse);
  CHECK(inverse->coefficients({3, 5, 0}) == Row{1, 2});
  CHECK_FALSE(left_inverse({{1, 1}, {2, 2}}, 2, tol));
  // (2, 2) repeats (1, 1): the first and the third are independent.
  CHECK(independent_rows({{1, 1, 0}, {2, 2, 0}, {0, 1, 1}}, 3, tol) == std::vector<std::size_t>{0, 2});
  CHECK(proportional({2, 4, 0}, {1, 2, 0}, tol));
  CHECK_FALSE(proportional({2, 4, 1}, {1, 2, 0}, tol));
  CHECK_FALSE(proportional({0, 0, 0}, {0, 0, 0}, tol));
}

TEST_CASE("Truth: an equation holds on every solution of the family, at every state", "[algebra]") {
  // x + y = 3 and x - y = a: x = (3 + a)/2, y = (3 - a)/2.
  const States states({{a, numeric(2), false}});
  std::vector<Sample> points{states.fixed(0), states.fixed(1)};
  std::mt19937 rng(3);
  for (int k = 0; k < 3; ++k) points.push_back(states.draw(rng));
  Family f;
  f.labels = {"sum", "difference"};
  f.residuals = {x + y - 3, x - y - a};
  f.unknowns = {x, y};
  const Truth truth(f, states, points, 2, {}, Tolerance{numeric(1, 1000000000)});
  REQUIRE(truth.usable());
  auto holds = [&](const ex& e) {
    const auto parts = linear_parts(e, f.unknowns);
    REQUIRE(parts);
    const auto v = truth.values(*parts);
    REQUIRE(v);
    return truth.holds(*v).answer;
  };
  CHECK(holds(2 * x - 3 - a) == Truth::Answer::holds);
  CHECK(holds(a * (x + y) - 3 * a) == Truth::Answer::holds);  // a times the first: a parameter's multiple
  CHECK(holds(x - a) == Truth::Answer::fails);
  // Not linear: x y = (9 - a^2)/4 at the solution; x y = 2 is not.
  CHECK(truth.holds_anyhow(x * y - (9 - a * a) / 4).answer == Truth::Answer::holds);
  CHECK(truth.holds_anyhow(x * y - 2).answer == Truth::Answer::fails);
  // Whatever x and y: (x + y)^2 - x^2 - 2 x y - y^2.
  CHECK(truth.vanishes(pow(x + y, 2) - x * x - 2 * x * y - y * y).answer == Truth::Answer::holds);
  CHECK(truth.vanishes(x + y - 3).answer == Truth::Answer::fails);
  // 2x = 3 + a is sum + difference (plain numbers); a x + a y = 3 a is a times the sum.
  const auto parts = linear_parts(2 * x - 3 - a, f.unknowns);
  const auto combination = truth.combination(*truth.values(*parts));
  REQUIRE(combination.size() == 2);
  CHECK(combination[0].plain);
  CHECK(combination[1].plain);
  const auto scaled = truth.combination(*truth.values(*linear_parts(a * x + a * y - 3 * a + x - y - a, f.unknowns)));
  REQUIRE(scaled.size() == 2);
  CHECK_FALSE(scaled[0].plain);  // a times the sum, beside once the difference
  CHECK_FALSE(scaled[1].plain);
  // Not a polynomial of degree one in the unknowns.
  CHECK_FALSE(linear_parts(sqrt(x * x) - x, f.unknowns));
  CHECK_FALSE(linear_parts(x * y, f.unknowns));
  CHECK_FALSE(linear_parts(sin(x), f.unknowns));
  // With only the fixed points, an equation that holds is not found to hold.
  const Truth fixed_only(f, states, {points[0], points[1]}, 2, {}, Tolerance{numeric(1, 1000000000)});
  const auto v = fixed_only.values(*linear_parts(2 * x - 3 - a, f.unknowns));
  CHECK(fixed_only.holds(*v).answer == Truth::Answer::unknown);
}
