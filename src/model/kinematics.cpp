#include "model/kinematics.hpp"

namespace tackle::kinematics {

using namespace GiNaC;

std::optional<Vec> velocity(const Model& m, const Body& b) {
  if (b.coord.is_zero()) return std::nullopt;
  if (m.dims() == 1) return Vec{b.rate, 0, 0};
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

Vec momentum_rate(const Body& b) { return b.mass * b.acceleration; }

Vec angular_momentum_rate(const Model& m, const Body& b, const Vec& about) {
  Vec h = cross(b.cm - about, momentum_rate(b));
  if (!b.inertia.is_zero()) h[2] += b.inertia * alpha(m, b);
  return h;
}

ex kinetic_energy(const Model& m, const Body& b, const std::function<ex(const ex&)>& in_state) {
  const auto v = velocity(m, b);
  ex e = v ? b.mass * in_state(m.dims() == 1 ? pow(b.rate, 2) : pow((*v)[0], 2) + pow((*v)[1], 2) + pow((*v)[2], 2)) / 2
           : ex(0);
  if (!b.inertia.is_zero()) e += b.inertia * in_state(pow(omega(m, b), 2)) / 2;
  return e;
}

ex kinetic_energy_rate(const Model& m, const Body& b, const Vec& v, const ex& w) {
  ex e = b.mass * inner(v, b.acceleration);
  if (!b.inertia.is_zero()) e += b.inertia * w * alpha(m, b);
  return e;
}

ex power(const Load& l, const Vec& v, const ex& w) {
  ex p = inner(l.force, v);
  if (!w.is_zero()) p += l.couple[2] * w;
  return p;
}

}  // namespace tackle::kinematics
