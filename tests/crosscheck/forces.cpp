// The forces on one body as the model has them at a state (Model::forces_on), for free body
// diagrams: from the model's own constraints and force laws, each at the point it acts at.
// A constraint's force on a point is its multiplier times the constraint's gradient there
// (times its sign: a string's tension pulls, a contact's force pushes), so a positive
// multiplier's direction is known from the geometry alone; its sense is known ahead of
// solving exactly where a requirement (model.hpp) keeps the multiplier from being negative.
#include <cmath>
#include <map>

#include "crosscheck/model.hpp"

namespace crosscheck {

namespace {

Eigen::VectorXd unit(const Eigen::VectorXd& v) { return v.norm() > 0 ? Eigen::VectorXd(v / v.norm()) : v; }

// A direction turned by `a` in the plane (other dimensions unchanged).
Eigen::VectorXd turned(const Eigen::VectorXd& v, double a) {
  if (v.size() != 2 || a == 0) return v;
  Eigen::VectorXd r(2);
  r << std::cos(a) * v(0) - std::sin(a) * v(1), std::sin(a) * v(0) + std::cos(a) * v(1);
  return r;
}

}  // namespace

bool Model::sense_known(const std::string& force) const {
  for (const auto& r : requirements_)
    if ((r.kind == Requirement::pulls || r.kind == Requirement::pushes) && r.force == force) return true;
  return false;
}

void Model::strand_parts(int body, const std::vector<PointRef>& pts, double sign, const std::string& what, bool sense,
                         const State& s, std::vector<ForcePart>& out) const {
  // The length of each strand k..k+1 has gradient -u at its first point and u at its second
  // (u from the first to the second): a force `sign` times the multiplier times that.
  for (std::size_t k = 0; k + 1 < pts.size(); ++k) {
    const Eigen::VectorXd u = unit(point_position(pts[k + 1], s) - point_position(pts[k], s));
    const std::string group = what + " strand " + std::to_string(k);
    if (pts[k].body == body) out.push_back({what, group + " first", pts[k].name, -sign * u, sense, false});
    if (pts[k + 1].body == body) out.push_back({what, group + " second", pts[k + 1].name, sign * u, sense, false});
  }
}

void Model::constraint_parts(int body, const Constraint& c, const State& s, std::vector<ForcePart>& out,
                             std::vector<BodyForce>& couples) const {
  const bool sense = sense_known(c.name);
  const std::string group = c.label + " at ";
  switch (c.kind) {
    case Constraint::path: strand_parts(body, c.points, c.g_sign, c.label, sense, s, out); break;
    case Constraint::length_expr: {
      const Body& b = bodies_[static_cast<std::size_t>(body)];
      const Eigen::VectorXd g = cons_derivs(c, s).grad.segment(b.q0, dims_);
      if (g.norm() > 0) out.push_back({c.label, group + b.name, b.name, c.g_sign * unit(g), sense, false});
      break;
    }
    case Constraint::project:
    case Constraint::roll:
      if (c.points[0].body != body) break;
      out.push_back({c.label, group + c.points[0].name, c.points[0].name, c.g_sign * c.dir, sense, false});
      if (c.mu != 0)
        out.push_back({c.label + " (its friction)", group + "friction", c.points[0].name, -c.sliding, true, false});
      break;
    case Constraint::relative:
      for (int side = 0; side < 2; ++side)
        if (c.points[static_cast<std::size_t>(side)].body == body) {
          const double sign = side == 0 ? 1.0 : -1.0;
          out.push_back({c.label, group + c.points[0].name, c.points[0].name, sign * c.dir, sense, false});
          // (sliding between two bodies: the friction against the first's slip, opposite on the other)
          if (c.mu != 0)
            out.push_back(
                {c.label + " (its friction)", group + "friction", c.points[0].name, -sign * c.sliding, true, false});
        }
      break;
    case Constraint::slide: {
      const Body& o = bodies_[static_cast<std::size_t>(c.other)];
      const Eigen::VectorXd across = o.r0 >= 0 ? turned(c.dir, s.q(o.r0)) : c.dir;
      if (c.points[0].body == body)
        out.push_back({c.label, group + c.points[0].name, c.points[0].name, across, false, false});
      if (c.other == body) out.push_back({c.label, group + c.points[0].name, c.points[0].name, -across, false, false});
      break;
    }
    case Constraint::rotation:
      if (c.body != body && c.other != body) break;
      if (dims_ != 2) throw Unsupported("a couple in space (" + c.label + ")");
      couples.push_back({c.label, bodies_[static_cast<std::size_t>(body)].name, {}, false, false, true, 0});
      break;
    default: break;  // (guides: tackle has no such force)
  }
}

void Model::load_forces(int body, const State& s, std::vector<BodyForce>& out) const {
  const std::vector<double> vars = numbers_at(s);
  for (const auto& l : loads_) {
    if (l.body != body) continue;
    for (const auto* part : {&l.force, &l.couple})
      for (const auto& e : *part)
        for (int k = first_coord_slot_; k < static_cast<int>(slot_names_.size()); ++k)
          if (e.uses(k) && slot_names_[static_cast<std::size_t>(k)].rfind("dot(", 0) == 0)
            throw Unsupported("a load that depends on the speed (" + l.label + "), which a sketch does not show");
    Eigen::VectorXd f(dims_);
    for (int i = 0; i < dims_; ++i) f(i) = l.force[static_cast<std::size_t>(i)].eval(vars);
    if (l.couple.empty()) {
      out.push_back({l.label, l.at.name, {unit(f)}, true, f.norm() < 1e-12, false, 0});
      continue;
    }
    if (dims_ != 2) throw Unsupported("a couple in space (" + l.label + ")");
    const double m = l.couple[0].eval(vars);
    out.push_back({l.label,
                   bodies_[static_cast<std::size_t>(body)].name,
                   {},
                   true,
                   m == 0,
                   true,
                   m > 0   ? 1
                   : m < 0 ? -1
                           : 0});
  }
}

std::vector<BodyForce> Model::forces_on(const std::string& name, const State& s) const {
  int body = -1;
  for (std::size_t i = 0; i < bodies_.size(); ++i)
    if (bodies_[i].name == name) body = static_cast<int>(i);
  if (body < 0) throw Unsupported("no body '" + name + "'");
  std::vector<BodyForce> out;
  const Body& b = bodies_[static_cast<std::size_t>(body)];
  if (b.mass > 0 && gravity_.norm() > 0) out.push_back({"gravity", b.name, {unit(gravity_)}, true, false, false, 0});
  load_forces(body, s, out);
  std::vector<ForcePart> parts;
  for (const auto& c : cons_)
    if (!c.guide) constraint_parts(body, c, s, parts, out);
  for (const auto& e : elements_) {
    if (e.kind == Element::damper)
      throw Unsupported("a damper (" + e.label + "): its force depends on the speed, which a sketch does not show");
    const double tension = element_tension(e, s);
    const std::size_t from = parts.size();
    strand_parts(body, e.points, tension < 0 ? 1.0 : -1.0, e.label, true, s, parts);
    for (std::size_t k = from; k < parts.size(); ++k) parts[k].zero = std::abs(tension) < 1e-9 * (1 + e.k);
  }
  // Parts of unknown sense at one point of one connection, two or more, are one force of
  // unknown direction (a pin's); every other part is a force of its own.
  std::map<std::string, std::vector<const ForcePart*>> groups;
  for (const auto& p : parts) groups[p.group].push_back(&p);
  for (const auto& [group, ps] : groups) {
    const bool free = ps.size() >= 2 && std::none_of(ps.begin(), ps.end(), [](const ForcePart* p) { return p->sense; });
    if (free) {
      BodyForce f{ps.front()->what, ps.front()->at, {}, false, false, false, 0};
      for (const auto* p : ps) f.lines.push_back(p->direction);
      out.push_back(f);
    } else {
      for (const auto* p : ps) out.push_back({p->what, p->at, {p->direction}, p->sense, p->zero, false, 0});
    }
  }
  return out;
}

}  // namespace crosscheck
