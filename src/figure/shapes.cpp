// The shapes the figures share: a body's outline (its own shape, a block, a bar, the box of
// its points), strands, the ground, a pin's support; a figure's bounds, moved and joined,
// and finished with its axes.
#include <algorithm>
#include <cmath>
#include <map>
#include <set>

#include "figure/figure.hpp"
#include "figure/geometry.hpp"
#include "figure/labels.hpp"
#include "model/kinematics.hpp"
#include "numeric/layout.hpp"

namespace tackle {

using namespace GiNaC;

namespace fig {

// Everything drawn, labels included: the figure's bounds.
void measure(Figure& f) {
  f.min_x = f.min_y = 1e300;
  f.max_x = f.max_y = -1e300;
  auto grow = [&](V p) {
    f.min_x = std::min(f.min_x, p.x);
    f.max_x = std::max(f.max_x, p.x);
    f.min_y = std::min(f.min_y, p.y);
    f.max_y = std::max(f.max_y, p.y);
  };
  auto grow_label = [&](const FigureLabel& l) {
    grow(vp(l.at) + V{l.width / 2, l.height / 2});
    grow(vp(l.at) - V{l.width / 2, l.height / 2});
  };
  for (const auto& o : f.outlines) {
    if (o.shape == FigureOutline::Shape::circle) {
      grow(vp(o.centre) + V{o.radius, o.radius});
      grow(vp(o.centre) - V{o.radius, o.radius});
    }
    for (const auto& c : o.corners) grow(vp(c));
  }
  for (const auto& l : f.lines)
    for (const auto& p : l.points) grow(vp(p));
  for (const auto& t : f.texts) grow_label(t);
  for (const auto& a : f.arrows) {
    grow(vp(a.from));
    grow(vp(a.to));
    grow_label(a.label);
  }
  for (const auto& c : f.couples) {
    grow(vp(c.centre) + V{c.radius, c.radius});
    grow(vp(c.centre) - V{c.radius, c.radius});
    grow_label(c.label);
  }
  for (const auto& d : f.dots) {
    grow(vp(d.at));
    if (d.label) grow_label(*d.label);
  }
}

void shift(Figure& f, V by) {
  auto move = [&](FigurePoint& p) { p = fp(vp(p) + by); };
  for (auto& o : f.outlines) {
    move(o.centre);
    for (auto& c : o.corners) move(c);
  }
  for (auto& l : f.lines)
    for (auto& p : l.points) move(p);
  for (auto& t : f.texts) move(t.at);
  for (auto& d : f.dots) {
    move(d.at);
    if (d.label) move(d.label->at);
  }
  for (auto& a : f.arrows) {
    move(a.from);
    move(a.to);
    move(a.label.at);
  }
  for (auto& c : f.couples) {
    move(c.centre);
    move(c.label.at);
  }
}

void append(Figure& f, const Figure& more) {
  f.outlines.insert(f.outlines.end(), more.outlines.begin(), more.outlines.end());
  f.lines.insert(f.lines.end(), more.lines.begin(), more.lines.end());
  f.texts.insert(f.texts.end(), more.texts.begin(), more.texts.end());
  f.dots.insert(f.dots.end(), more.dots.begin(), more.dots.end());
  f.arrows.insert(f.arrows.end(), more.arrows.begin(), more.arrows.end());
  f.couples.insert(f.couples.end(), more.couples.begin(), more.couples.end());
}

void finish(Figure& f, const std::vector<V>& directions, const std::vector<std::string>& names) {
  settle_labels(f);  // the figure whole: each label clear of everything drawn (figure/labels.hpp)
  // Bounds, then the axes at the lower left, outside everything else, and the bounds again.
  measure(f);
  const V origin{f.min_x - 1.3, f.min_y + 0.2};
  for (std::size_t k = 0; k < directions.size(); ++k) {
    FigureArrow a;
    a.axis = true;
    a.from = fp(origin);
    const V d = directions[k];
    a.to = fp(origin + 0.8 * d);
    a.label.tex = names[k];
    a.label.width = char_width + 0.12;
    a.label.height = label_height;
    a.label.at = fp(origin + 1.05 * d);
    f.arrows.push_back(a);
  }
  measure(f);
}

namespace {

// A body's box in model space: the bounding box of its points (reaching as far beyond a
// center of mass on one of its edges), and its longest side before that.
struct Bounds {
  std::array<double, 3> lo, hi;
  double longest = 0;
};

// What the ways of drawing a body share: the body, its points (model units), how they go
// onto paper, and the body as drawn so far.
struct BodyShape {
  const Model& m;
  const Body& b;
  const std::vector<std::array<double, 3>>& points;
  const Projection& proj;
  double scale;
  const Number& num;
  Drawn& d;

  // A turning particle (a pendulum's bob): a small disk at its center, the forces at it.
  void turning_particle() {
    d.outline.shape = FigureOutline::Shape::circle;
    d.outline.centre = fp(d.centre);
    d.outline.radius = 0.3;
    d.particle = true;
  }

  // Its own shape (`draw:`) turned by the body's angle where it has one: a circle, a rod (a
  // little longer, so that no force at an end runs along an edge), else a rectangle.
  void own_shape(double side, double overhang) {
    const double unit = proj.dims == 1 ? side : scale;
    const double turned = proj.dims == 2 ? num(b.angle).value_or(0) + proj.turn : 0;
    const V along{std::cos(turned), std::sin(turned)};
    if (b.drawn_shape == "circle" || b.drawn_shape == "spool") {
      d.outline.shape = FigureOutline::Shape::circle;
      d.outline.centre = fp(d.centre);
      d.outline.radius = unit * num(b.drawn_size[0]).value_or(1) / 2;
      if (b.drawn_shape == "spool") d.hub = unit * num(b.drawn_size[1]).value_or(0) / 2;
    } else if (b.drawn_shape == "wedge") {
      // A right triangle on its base about its centroid: the right angle a third of the base
      // and of the height from it, the sloping face towards `face`.
      const double base = unit * num(b.drawn_size[0]).value_or(1), height = unit * num(b.drawn_size[1]).value_or(1);
      const double s = b.drawn_face_left ? -1 : 1;
      const V up = perp(along);
      for (const V c : {V{-base / 3, -height / 3}, V{2 * base / 3, -height / 3}, V{-base / 3, 2 * height / 3}})
        d.outline.corners.push_back(fp(d.centre + (s * c.x) * along + c.y * up));
      if (s < 0) std::reverse(d.outline.corners.begin(), d.outline.corners.end());  // counterclockwise
    } else if (b.drawn_shape == "rod") {
      const double length = unit * num(b.drawn_size[0]).value_or(1);
      d.outline = rectangle(d.centre, along, length + overhang, std::min(0.35, 0.12 * length));
    } else {
      d.outline =
          rectangle(d.centre, along, unit * num(b.drawn_size[0]).value_or(1), unit * num(b.drawn_size[1]).value_or(1));
    }
    d.outline.name = b.name;
    d.particle = proj.dims == 1 || points.size() <= 1;  // else forces at their points
  }

  // Whether every point is in one place (a particle).
  bool one_place() const {
    for (const auto& p : points)
      for (int k = 0; k < 3; ++k)
        if (std::fabs(p[k] - points[0][k]) > 1e-9 * (1 + std::fabs(p[k]))) return false;
    return true;
  }

  // A particle: a pulley block's disk (1-D, no mass), else a block `side` wide turned to its
  // line of motion (`along`, else its acceleration's), as a block on an incline is drawn.
  void particle(std::optional<V> along, double side) {
    d.particle = true;
    if (proj.dims == 1 && (!b.has_mass || b.mass.is_zero())) {
      d.outline.shape = FigureOutline::Shape::circle;
      d.outline.centre = fp(d.centre);
      d.outline.radius = 0.45;
    } else {
      V way{1, 0};
      if (along) {
        way = *along;
      } else if (proj.dims > 1) {
        way = acceleration_way();
      }
      d.outline = rectangle(d.centre, way, side, side * 0.8);
    }
    d.outline.name = b.name;
  }

  // The direction of its acceleration on paper, pointing right: the coefficient of the
  // unknown in it, or the given vector (along x where it cannot be evaluated).
  V acceleration_way() const {
    V way{1, 0};
    const Vec acceleration = kinematics::acceleration(m, b);
    std::optional<ex> u;
    for (const ex& c : m.candidates)
      for (int k = 0; k < m.dims() && !u; ++k)
        if (acceleration[k].has(c)) u = c;
    std::array<double, 3> a{0, 0, 0};
    bool ok = true;
    for (int k = 0; k < m.dims(); ++k) {
      const ex ak = u ? acceleration[k].expand().coeff(*u, 1) : acceleration[k];
      auto v = num(ak);
      if (!v)
        ok = false;
      else
        a[k] = *v;
    }
    if (ok && len(proj(a)) > 1e-9) way = normalized(proj(a));
    if (way.x < 0) way = -1 * way;
    return way;
  }

  // The bounding box of its points; a center of mass on an edge of the box (a suitcase's at
  // the height h of its middle): the body reaches as far beyond it.
  Bounds bounds() const {
    Bounds x{points[0], points[0]};
    for (const auto& p : points)
      for (int k = 0; k < 3; ++k) {
        x.lo[k] = std::min(x.lo[k], p[k]);
        x.hi[k] = std::max(x.hi[k], p[k]);
      }
    for (int k = 0; k < 3; ++k) x.longest = std::max(x.longest, x.hi[k] - x.lo[k]);
    if (b.has_cm)
      if (auto cm = point3(m, num, b.cm))
        for (int k = 0; k < 3; ++k) {
          const double span = x.hi[k] - x.lo[k];
          if (span <= 0.08 * x.longest) continue;
          if ((*cm)[k] >= x.hi[k] - 0.02 * span)
            x.hi[k] = x.lo[k] + 2 * span;
          else if ((*cm)[k] <= x.lo[k] + 0.02 * span)
            x.lo[k] = x.hi[k] - 2 * span;
        }
    return x;
  }

  // From its points: a bar from the farthest pair of them (a little longer, so that no force
  // at an end runs along an edge) where the box spreads along one axis, else the box's
  // outline (a plate or a box); centred in its corners without a center of mass.
  void from_points(double overhang) {
    const Bounds x = bounds();
    int spread = 0;
    for (int k = 0; k < 3; ++k) spread += x.hi[k] - x.lo[k] > 0.08 * x.longest;
    if (spread <= 1) {
      V a = scale * proj(points[0]), c = a;
      double far = -1;
      for (const auto& p : points)
        for (const auto& q : points)
          if (len(proj(p) - proj(q)) > far) {
            far = len(proj(p) - proj(q));
            a = scale * proj(p);
            c = scale * proj(q);
          }
      d.outline = rectangle(0.5 * (a + c), c - a, len(c - a) + overhang, std::min(1.0, 0.3 * len(c - a)));
      d.outline.name = b.name;
    } else {
      std::vector<V> corners;
      for (int c = 0; c < 8; ++c) {
        std::array<double, 3> p{(c & 1) ? x.hi[0] : x.lo[0], (c & 2) ? x.hi[1] : x.lo[1], (c & 4) ? x.hi[2] : x.lo[2]};
        corners.push_back(scale * proj(p));
      }
      d.outline.corners = convex_hull(corners);
    }
    V sum{0, 0};
    for (const auto& c : d.outline.corners) sum = sum + vp(c);
    if (!b.has_cm) d.centre = (1.0 / static_cast<double>(d.outline.corners.size())) * sum;
  }
};

}  // namespace

Drawn draw_body(const Model& m, int body, const std::vector<std::array<double, 3>>& points, const Projection& proj,
                double scale, const Number& num, V centre, std::optional<V> along, double side, double overhang) {
  const Body& b = m.bodies[body];
  Drawn d;
  d.body = body;
  d.outline.name = b.name;
  d.centre = centre;
  BodyShape shape{m, b, points, proj, scale, num, d};
  if (b.drawn_shape.empty() && proj.dims == 2 && !b.angle.is_zero() && b.inertia.is_zero()) {
    shape.turning_particle();
  } else if (!b.drawn_shape.empty()) {
    shape.own_shape(side, overhang);
  } else if (proj.dims == 1 || points.size() <= 1 || shape.one_place()) {
    shape.particle(along, side);
  } else {
    shape.from_points(overhang);
  }
  return d;
}

std::vector<FigurePoint> zigzag(V a, V b, V across) {
  // Straight leads, then coils.
  const double l = len(b - a);
  const V u = normalized(b - a);
  const double lead = std::min(0.25, 0.2 * l);
  const int n = std::max(4, static_cast<int>((l - 2 * lead) / 0.22));
  std::vector<FigurePoint> out{fp(a), fp(a + lead * u)};
  for (int i = 0; i < n; ++i) {
    const double t = lead + (i + 0.5) * (l - 2 * lead) / n;
    out.push_back(fp(a + t * u + ((i % 2 ? -1 : 1) * 0.18) * across));
  }
  out.push_back(fp(b - lead * u));
  out.push_back(fp(b));
  return out;
}

void draw_strand(Figure& f, const std::string& as, V p, V q, V across) {
  if (as == "spring") {
    f.lines.push_back({zigzag(p, q, across), false});
  } else if (as == "damper") {
    // A dashpot: the cylinder open towards the far end, the piston in it.
    const V u = normalized(q - p);
    const double l = len(q - p), mid = l / 2, h = 0.22, w = std::min(0.35, 0.3 * l);
    f.lines.push_back({{fp(p), fp(p + (mid - w) * u)}, false});
    f.lines.push_back({{fp(p + (mid + w) * u + h * across), fp(p + (mid - w) * u + h * across),
                        fp(p + (mid - w) * u - h * across), fp(p + (mid + w) * u - h * across)},
                       false});
    f.lines.push_back({{fp(p + mid * u + 0.7 * h * across), fp(p + mid * u - 0.7 * h * across)}, false});
    f.lines.push_back({{fp(p + mid * u), fp(q)}, false});
  } else {
    f.lines.push_back({{fp(p), fp(q)}, false});
  }
}

void draw_ground(Figure& f, V a, V b, V into) {
  f.lines.push_back({{fp(a), fp(b)}, false});
  const double l = len(b - a);
  const V u = normalized(b - a);
  for (double s = 0; s <= l + 1e-9; s += hatch_step)
    f.lines.push_back({{fp(a + s * u), fp(a + s * u + hatch * into + hatch * u)}, true});
}

void draw_support(Figure& f, V p, V below_of) {
  if (len(below_of - p) < 0.05 || dot(below_of - p, down) > 0.5 * len(below_of - p)) {
    double top = p.y + 0.7;
    for (const auto& o : f.outlines)
      if (o.shape == FigureOutline::Shape::circle && len(vp(o.centre) - p) < o.radius)
        top = std::max(top, o.centre.y + o.radius + 0.35);
    f.lines.push_back({{fp(p), fp(V{p.x, top})}, false});
    draw_ground(f, V{p.x - support_width / 2, top}, V{p.x + support_width / 2, top}, V{0, 1});
  } else {
    f.lines.push_back({{fp(p), fp(p + V{-0.3, -pin_drop}), fp(p + V{0.3, -pin_drop}), fp(p)}, false});
    draw_ground(f, p + V{-support_width / 2, -pin_drop}, p + V{support_width / 2, -pin_drop}, down);
  }
}

namespace {

// How far up its slope an incline's triangle reaches: to its top, or short of a body beside
// it that neither rests on it nor stands above it (a block hanging by its top); none where
// that leaves less than half of it.
std::optional<V> incline_end(V n, V foot, V top, const std::vector<std::optional<Drawn>>& drawn) {
  const double way = top.x > foot.x ? 1 : -1, offset = dot(foot, n);
  double x = top.x;
  for (const auto& d : drawn) {
    if (!d) continue;
    if (extent_along(d->outline, n).first > offset - 0.05) continue;  // on it, or above it
    const auto [x0, x1] = extent_along(d->outline, V{1, 0});
    if (extent_along(d->outline, V{0, 1}).first >= top.y || x1 <= std::min(foot.x, x) || x0 >= std::max(foot.x, x))
      continue;
    x = way > 0 ? std::min(x, x0 - 0.15) : std::max(x, x1 + 0.15);
  }
  if (way * (x - foot.x) < 0.5 * way * (top.x - foot.x)) return std::nullopt;
  return foot + ((x - foot.x) / (top.x - foot.x)) * (top - foot);
}

}  // namespace

bool draw_incline(Figure& f, V n, V foot, V top, const std::vector<std::optional<Drawn>>& drawn) {
  const std::optional<V> end = incline_end(n, foot, top, drawn);
  if (!end) return false;
  const V corner{end->x, foot.y};
  FigureOutline o;
  o.corners = {fp(foot), fp(corner), fp(*end)};
  if (cross(corner - foot, *end - foot) < 0) std::swap(o.corners[1], o.corners[2]);  // counterclockwise
  f.outlines.insert(f.outlines.begin(), o);                                          // behind the bodies
  draw_ground(f, foot + (foot.x < corner.x ? -0.3 : 0.3) * V{1, 0}, corner, down);
  if (len(top - *end) > 0.05) draw_ground(f, *end, top, -1 * n);  // on past a body beside it
  return true;
}

void draw_wheel(Figure& f, V contact, V n) {
  FigureOutline o;
  o.shape = FigureOutline::Shape::circle;
  o.centre = fp(contact + wheel_radius * n);
  o.radius = wheel_radius;
  f.outlines.push_back(o);
}

std::map<int, V> strands_at(const Model& m, const std::set<int>& pulleys, const std::function<V(int)>& paper) {
  std::map<int, V> at;
  for (const auto& d : m.drawings)
    if (d.as == "line" || d.as == "spring" || d.as == "damper")
      for (std::size_t k = 0; k < d.path.size(); ++k)
        if (pulleys.count(d.path[k]))
          for (std::size_t j : {k - 1, k + 1})
            if (j < d.path.size() && len(paper(d.path[j]) - paper(d.path[k])) > 1e-9)
              at[d.path[k]] = at[d.path[k]] + normalized(paper(d.path[j]) - paper(d.path[k]));
  return at;
}

V on_face(const FigureOutline& base, const Drawn& rider, V normal) {
  const V c = rider.centre;
  const auto [lo, hi] = extent_along(rider.outline, normal);
  const V face = inside(base, c) ? exit_point(base, c, normal) : c - boundary_distance(base, c) * normal;
  return face + ((hi - lo) / 2) * normal;
}

std::optional<std::array<double, 3>> point3(const Model& m, const Number& num, const Vec& v) {
  return point_at(m, num, v);
}

}  // namespace fig

}  // namespace tackle
