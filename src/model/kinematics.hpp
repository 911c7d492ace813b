// Kinematics and momenta of a body: one home for what every stage asks of a body's motion.
// A body has a pose (its center of mass, and an angle: 0 for one that only translates), a
// mass and a moment of inertia about its center; a point of a body is the body plus an
// offset. The balances (AMB's rate of angular momentum), the motion (kinetic energy), the
// power check and the sliding direction's check call these, never copies of their own.
#pragma once

#include <functional>
#include <optional>

#include "model/model.hpp"

namespace tackle::kinematics {

/// The body's translation coordinate (x_A, s) with its rate and acceleration, from the
/// model's coordinates; nothing for a body that has none (it only turns, is still, or has its
/// acceleration given).
[[nodiscard]] const Coordinate* translation(const Model& m, const Body& b);

/// The acceleration of the body's center of mass, a_G = d^2 r_G/dt^2 by the chain rule on the
/// model's coordinates (1-D: ddot(x_A)); for a body with no coordinate, as given.
[[nodiscard]] Vec acceleration(const Model& m, const Body& b);

/// The symbol of the body's acceleration: its translation coordinate's, ddot(x_A), or the
/// unknown magnitude along its given line, a_B; 0 when it has neither.
[[nodiscard]] GiNaC::ex acceleration_symbol(const Model& m, const Body& b);

/// The velocity of the body's center of mass in the coordinates' rates (1-D: its rate);
/// nothing for a body with no coordinate (at rest, or with only its acceleration given).
/// `b` is one of `m.bodies`.
[[nodiscard]] std::optional<Vec> velocity(const Model& m, const Body& b);

/// The body's angular velocity and acceleration about the plane's normal (0 while it only
/// translates).
[[nodiscard]] GiNaC::ex omega(const Model& m, const Body& b);
[[nodiscard]] GiNaC::ex alpha(const Model& m, const Body& b);

/// The velocity of the point at `offset` from the body's center of mass (in the ground's
/// axes): v + omega x r.
[[nodiscard]] std::optional<Vec> point_velocity(const Model& m, const Body& b, const Vec& offset);

/// The rate of change of the body's linear momentum, m a_G.
[[nodiscard]] Vec momentum_rate(const Model& m, const Body& b);

/// The rate of change of the body's angular momentum about the point `about` (fixed, or the
/// center of mass): r_G/about x m a + I alpha (about the plane's normal).
[[nodiscard]] Vec angular_momentum_rate(const Model& m, const Body& b, const Vec& about);

/// The kinetic energy, m v.v/2 + I omega^2/2; `in_state` is applied to v.v and omega^2 (the
/// motion puts the dependent rates in there).
[[nodiscard]] GiNaC::ex kinetic_energy(const Model& m, const Body& b,
                                       const std::function<GiNaC::ex(const GiNaC::ex&)>& in_state);

/// The rate of change of the kinetic energy for a body moving at `v` (with `w` its angular
/// velocity): m v.a + I w alpha.
[[nodiscard]] GiNaC::ex kinetic_energy_rate(const Model& m, const Body& b, const Vec& v, const GiNaC::ex& w);

/// The power of a load on body `b`, whose center of mass moves at `v` and which turns at `w`:
/// F.v_P + M w, with v_P = v + w x r the velocity of the load's point.
[[nodiscard]] GiNaC::ex power(const Body& b, const Load& l, const Vec& v, const GiNaC::ex& w);

}  // namespace tackle::kinematics
