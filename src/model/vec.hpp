// Three-component vectors of expressions. Every position, force and moment is a Vec; a
// problem with n axes uses the first n components (a 2-D moment is the z component).
#pragma once

#include <array>

#include <ginac/ginac.h>

#include "expr/trig.hpp"

namespace tackle {

using Vec = std::array<GiNaC::ex, 3>;

inline Vec zero_vec() { return {0, 0, 0}; }
inline Vec operator+(const Vec& a, const Vec& b) { return {a[0] + b[0], a[1] + b[1], a[2] + b[2]}; }
inline Vec operator-(const Vec& a, const Vec& b) { return {a[0] - b[0], a[1] - b[1], a[2] - b[2]}; }
inline Vec operator*(const GiNaC::ex& s, const Vec& a) { return {s * a[0], s * a[1], s * a[2]}; }
inline Vec cross(const Vec& a, const Vec& b) {
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}
inline GiNaC::ex inner(const Vec& a, const Vec& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
/// |a|, with sin^2 + cos^2 = 1 used when that shortens what is under the root.
inline GiNaC::ex norm(const Vec& a) { return GiNaC::sqrt(fewer_trig_terms(inner(a, a).expand())); }
inline Vec unit(const Vec& a) { return (1 / norm(a)) * a; }
inline bool is_zero_vec(const Vec& a) {
  return GiNaC::normal(a[0]).is_zero() && GiNaC::normal(a[1]).is_zero() && GiNaC::normal(a[2]).is_zero();
}

}  // namespace tackle
