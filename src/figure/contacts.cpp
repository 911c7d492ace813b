// Contacts as the figures draw them: which unknowns are contacts' normal forces, and which
// bodies press on each other through their centers (figure/geometry.hpp).
#include <map>

#include "figure/geometry.hpp"

namespace tackle::fig {

using namespace GiNaC;

bool contact_normal(const Model& m, const ex& u) {
  return std::any_of(m.conditions.begin(), m.conditions.end(), [&](const Condition& c) {
    const bool says = c.meaning.find("push") != std::string::npos || c.meaning.find("press") != std::string::npos;
    return says && (c.op == ">=" || c.op == ">") && c.rhs.is_zero() && c.lhs.is_equal(u);
  });
}

namespace {

// A contact between bodies as its loads give it: the bodies its normal force acts on, and on
// each the force per unit of that normal force (model units, at the layout's numbers).
struct Pressing {
  std::vector<int> bodies;
  std::vector<std::array<double, 3>> normals;
};

std::map<std::string, Pressing> pressing(const Model& m, const Number& num) {
  std::vector<ex> normals;
  for (const ex& u : m.candidates)
    if (contact_normal(m, u)) normals.push_back(u);
  std::map<std::string, Pressing> out;  // by connection
  for (const auto& l : m.loads) {
    if (l.body < 0) continue;
    Vec force = zero_vec();
    for (int k = 0; k < 3; ++k) force[k] = l.force[k].expand();
    for (const ex& u : normals) {
      Vec c = zero_vec();
      for (int k = 0; k < 3; ++k) c[k] = force[k].coeff(u, 1);
      const auto n = point3(m, num, c);
      if (is_zero_vec(c) || !n) continue;
      out[force_key(l.origin)].bodies.push_back(l.body);
      out[force_key(l.origin)].normals.push_back(*n);
    }
  }
  return out;
}

// The line of two bodies' centers on paper, along the normal of their contact.
bool through_centers(const Projection& proj, V line, const std::array<double, 3>& normal) {
  const V n = proj(normal);
  return len(line) > 1e-9 && len(n) > 1e-12 && std::fabs(dot(normalized(line), normalized(n))) >= 0.95;
}

}  // namespace

std::vector<Stacked> stacked(const Model& m, const Number& num, const Projection& proj,
                             const std::vector<std::vector<std::array<double, 3>>>& body_points) {
  std::vector<Stacked> out;
  for (const auto& [key, p] : pressing(m, num)) {
    if (p.bodies.size() != 2 || p.bodies[0] == p.bodies[1]) continue;
    const auto &pa = body_points[p.bodies[0]], &pb = body_points[p.bodies[1]];
    if (pa.empty() || pb.empty()) continue;
    const V line = proj(pa[0]) - proj(pb[0]);
    if (!through_centers(proj, line, p.normals.back())) continue;
    out.push_back({p.bodies[0], p.bodies[1], len(line), std::fabs(line.y) > std::fabs(line.x) ? 0.8 : 1.0});
  }
  return out;
}

std::vector<Resting> resting(const Model& m, const Number& num, const Projection& proj,
                             const std::vector<std::vector<std::array<double, 3>>>& body_points) {
  std::vector<Resting> out;
  for (const auto& [key, p] : pressing(m, num)) {
    if (p.bodies.size() != 2 || p.bodies[0] == p.bodies[1]) continue;
    for (int r : {0, 1}) {
      const int rider = p.bodies[r], base = p.bodies[1 - r];
      const auto &pr = body_points[rider], &pb = body_points[base];
      if (pr.empty() || pb.empty() || m.bodies[base].drawn_shape.empty() || !m.bodies[rider].drawn_shape.empty())
        continue;
      if (through_centers(proj, proj(pr[0]) - proj(pb[0]), p.normals[r])) continue;  // stacked
      const V n = proj(p.normals[r]);
      if (len(n) > 1e-12) out.push_back({rider, base, normalized(n)});
    }
  }
  return out;
}

}  // namespace tackle::fig
