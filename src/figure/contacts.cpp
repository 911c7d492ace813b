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

std::vector<Stacked> stacked(const Model& m, const Number& num, const Projection& proj,
                             const std::vector<std::vector<std::array<double, 3>>>& body_points) {
  std::vector<ex> normals;
  for (const ex& u : m.candidates)
    if (contact_normal(m, u)) normals.push_back(u);
  std::map<std::string, std::vector<int>> bodies_of;  // a connection's pressing loads' bodies
  std::map<std::string, std::array<double, 3>> normal_of;
  for (const auto& l : m.loads) {
    if (l.body < 0) continue;
    Vec force = zero_vec();
    for (int k = 0; k < 3; ++k) force[k] = l.force[k].expand();
    for (const ex& u : normals) {
      Vec c = zero_vec();
      for (int k = 0; k < 3; ++k) c[k] = force[k].coeff(u, 1);
      const auto n = point3(m, num, c);
      if (is_zero_vec(c) || !n) continue;
      bodies_of[force_key(l.origin)].push_back(l.body);
      normal_of[force_key(l.origin)] = *n;
    }
  }
  std::vector<Stacked> out;
  for (const auto& [key, bodies] : bodies_of) {
    if (bodies.size() != 2 || bodies[0] == bodies[1]) continue;
    const auto &pa = body_points[bodies[0]], &pb = body_points[bodies[1]];
    if (pa.empty() || pb.empty()) continue;
    const V line = proj(pa[0]) - proj(pb[0]), n = proj(normal_of[key]);
    if (len(line) < 1e-9 || len(n) < 1e-12 || std::fabs(dot(normalized(line), normalized(n))) < 0.95) continue;
    out.push_back({bodies[0], bodies[1], len(line), std::fabs(line.y) > std::fabs(line.x) ? 0.8 : 1.0});
  }
  return out;
}

}  // namespace tackle::fig
