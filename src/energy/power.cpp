#include "energy/power.hpp"

#include <algorithm>

#include "expr/print.hpp"
#include "expr/rational.hpp"
#include "expr/trig.hpp"
#include "model/kinematics.hpp"

namespace tackle {

using namespace GiNaC;

PowerCheck check_power(const Model& m, const EquationSystem& s, const Solution& sol) {
  PowerCheck c;
  if (sol.status == Solution::Status::inconsistent) {
    c.reason = "the equations are inconsistent";
    return c;
  }
  if (!sol.unsolved.empty()) {
    c.reason = "the instant is not solved (nothing is asked at it)";
    return c;
  }
  // Each body's velocity: from its coordinate (the center of mass differentiated), or, for a
  // body that moves without one, a speed along its (straight) line of motion.
  std::vector<Vec> velocity(m.bodies.size(), zero_vec());
  bool moving = false;
  for (std::size_t i = 0; i < m.bodies.size(); ++i) {
    const Body& b = m.bodies[i];
    if (const auto v = kinematics::velocity(m, b)) {
      velocity[i] = *v;
      moving = true;
    } else if (!is_zero_vec(b.given_acceleration)) {
      // Straight-line motion: the velocity is along the acceleration, a signed speed v_B
      // along the one axis it has, or along the vector itself.
      int nonzero = 0, axis = 0;
      for (int k = 0; k < 3; ++k)
        if (!b.given_acceleration[k].is_zero()) ++nonzero, axis = k;
      const symbol v("v_" + b.name, "v_{" + b.name + "}");
      c.speeds.push_back(v);
      if (nonzero == 1)
        velocity[i][axis] = v;
      else
        velocity[i] = v * b.given_acceleration;
      moving = true;
    }
  }
  if (!moving) {
    c.reason = "every body is at rest";
    return c;
  }
  // Each sum made once from its terms (adding term by term copies the sum each time: a
  // chain of 256 has 256 of them).
  exvector kinetic, power;
  for (std::size_t i = 0; i < m.bodies.size(); ++i)
    if (m.bodies[i].has_mass)
      kinetic.push_back(
          kinematics::kinetic_energy_rate(m, m.bodies[i], velocity[i], kinematics::omega(m, m.bodies[i])));
  for (const auto& l : m.loads)
    if (l.body >= 0)
      power.push_back(kinematics::power(m.bodies[l.body], l, velocity[l.body], kinematics::omega(m, m.bodies[l.body])));
  c.kinetic_rate = add(kinetic);
  c.power = add(power);
  // sin^2 + cos^2 = 1 where that leaves fewer terms (a block on an incline: m v a, not
  // m v a cos^2 + m v a sin^2).
  c.kinetic_rate = fewer_trig_terms(c.kinetic_rate.expand());
  c.power = fewer_trig_terms(c.power.expand());

  // The velocities obey the constraints: the rate equations solved for as many rates as they
  // fix, in terms of the rest.
  std::vector<ex> rates;
  for (const auto& c : m.coordinates)
    if (!contains(m.given, c.rate)) rates.push_back(c.rate);
  exmap rate_values;
  if (!s.rate_equations.empty() && !rates.empty()) {
    const Solution r = solve_equations(m.file, s.rate_equations, rates);
    if (r.status == Solution::Status::inconsistent) {
      c.reason = "the constraints' rates are inconsistent";
      return c;
    }
    rate_values = r.general;
  }
  const ex balance = c.kinetic_rate - c.power;
  // The solution is put in at random exact points, each value evaluated once, as the
  // solver's own check does (a residual that is not zero vanishes at such a point by chance
  // with a probability of its degree over 2^40); the residual is written out and put in
  // normal form only when it is shown, that is when it is not zero, or when it is not a
  // rational function (sin(theta)).
  if (m.lengths.empty())
    if (const auto zero = zero_at_random_points(balance, {&sol.general, &rate_values}); zero && *zero) {
      c.residual = 0;
      c.status = PowerCheck::Status::holds;
      return c;
    }
  const ex residual = substituted(substituted(balance, sol.general), rate_values);
  // Every force must be known: a chosen set of balances may leave some out. (Symbols
  // gathered once: has() of each candidate would be quadratic.)
  const auto present = symbols_in(residual);
  for (const auto& u : m.candidates)
    if (present.count(u) != 0 && !contains(sol.free, u)) {
      c.reason = "the balances chosen do not give " + to_text(u);
      return c;
    }
  c.residual = normal(reduced_on_lengths(residual, m));
  if (has_trig(c.residual))
    for (const bool to_cos : {true, false})
      if (const ex t = normal(pythagoras(c.residual, to_cos)); t.is_zero()) c.residual = t;
  c.status = c.residual.is_zero() ? PowerCheck::Status::holds : PowerCheck::Status::fails;
  return c;
}

}  // namespace tackle
