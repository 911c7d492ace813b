#include "model/kinematics.hpp"

#include <algorithm>

#include "expr/trig.hpp"

namespace tackle::kinematics {

using namespace GiNaC;

namespace {

int index_of(const Model& m, const Body& b) { return static_cast<int>(&b - m.bodies.data()); }

}  // namespace

const Coordinate* translation(const Model& m, const Body& b) {
  const int index = index_of(m, b);
  for (const auto& c : m.coordinates)
    if (c.body == index && c.kind == Coordinate::Kind::translation) return &c;
  return nullptr;
}

Vec acceleration(const Model& m, const Body& b) {
  const int index = index_of(m, b);
  if (std::none_of(m.coordinates.begin(), m.coordinates.end(), [&](const Coordinate& c) { return c.body == index; }))
    return b.given_acceleration;
  if (m.dims() == 1) return Vec{translation(m, b)->accel, 0, 0};
  Vec a = zero_vec();
  for (int k = 0; k < 3; ++k) a[k] = time_derivative(time_derivative(b.cm[k], m), m);
  return a;
}

ex acceleration_symbol(const Model& m, const Body& b) {
  const Coordinate* q = translation(m, b);
  return q ? q->accel : b.along_unknown;
}

std::optional<Vec> velocity(const Model& m, const Body& b) {
  const int index = index_of(m, b);
  const bool moves =
      std::any_of(m.coordinates.begin(), m.coordinates.end(), [&](const Coordinate& c) { return c.body == index; });
  if (!moves) return std::nullopt;
  if (m.dims() == 1) return Vec{translation(m, b)->rate, 0, 0};
  Vec v = zero_vec();
  for (int k = 0; k < 3; ++k) v[k] = time_derivative(b.cm[k], m);
  return v;
}

ex omega(const Model& m, const Body& b) { return b.angle.is_zero() ? ex(0) : time_derivative(b.angle, m); }

ex alpha(const Model& m, const Body& b) {
  return b.angle.is_zero() ? ex(0) : time_derivative(time_derivative(b.angle, m), m);
}

std::optional<Vec> point_velocity(const Model& m, const Body& b, const Vec& offset) {
  auto v = velocity(m, b);
  if (!v) return v;
  const ex w = omega(m, b);
  if (w.is_zero()) return v;
  return *v + cross(Vec{0, 0, w}, offset);
}

Vec momentum_rate(const Model& m, const Body& b) { return b.mass * acceleration(m, b); }

Vec angular_momentum_rate(const Model& m, const Body& b, const Vec& about) {
  Vec h = cross(b.cm - about, momentum_rate(m, b));
  if (b.angle.is_zero()) return h;
  // Turning: I alpha, and sin^2 + cos^2 = 1 where the lever arm turns with the body (a bar
  // about its pin: m L^2/4 ddot(theta), not m L^2/4 (cos^2 + sin^2) ddot(theta)).
  h[2] = fewer_trig_terms((h[2] + b.inertia * alpha(m, b)).expand());
  return h;
}

ex kinetic_energy(const Model& m, const Body& b, const std::function<ex(const ex&)>& in_state) {
  const auto v = velocity(m, b);
  ex e = v ? b.mass * in_state(pow((*v)[0], 2) + pow((*v)[1], 2) + pow((*v)[2], 2)) / 2 : ex(0);
  if (!b.inertia.is_zero()) e += b.inertia * in_state(pow(omega(m, b), 2)) / 2;
  return e;
}

ex kinetic_energy_rate(const Model& m, const Body& b, const Vec& v, const ex& w) {
  ex e = b.mass * inner(v, acceleration(m, b));
  if (!b.inertia.is_zero()) e += b.inertia * w * alpha(m, b);
  return e;
}

ex power(const Body& b, const Load& l, const Vec& v, const ex& w) {
  if (w.is_zero()) return inner(l.force, v);
  // The point of application moves at v + w x r (r from the center of mass).
  const Vec at = l.at ? cross(Vec{0, 0, w}, *l.at - b.cm) : zero_vec();
  return inner(l.force, v + at) + l.couple[2] * w;
}

}  // namespace tackle::kinematics
