// Free body diagrams from the model's geometry: outlines, arrows at their points, labels
// placed where nothing else is.
#include <algorithm>
#include <cmath>
#include <functional>
#include <map>
#include <set>

#include "expr/print.hpp"
#include "expr/trig.hpp"
#include "figure/figure.hpp"
#include "figure/geometry.hpp"
#include "figure/labels.hpp"
#include "model/forces.hpp"
#include "model/kinematics.hpp"
#include "numeric/layout.hpp"

namespace tackle {

using namespace GiNaC;
using namespace fig;

namespace {

// One force, or one component of it, to draw: where it acts (model units, or none for a 1-D
// body or a body drawn around one point), its direction on paper, its label.
struct Pending {
  int body = -1;
  std::optional<std::array<double, 3>> at;
  V direction;
  ex label;
  bool dashed = false;
  bool at_cm = false;  // acts at the center of mass: drawn pulling away from it
  bool push = false;   // a contact's normal force (N >= 0: "the contact pushes"): drawn pressing on the outline
};

// The steps of a free body diagram and what they share: the bodies drawn, the forces to
// draw (from outside the system only), and the figure they draw into.
struct FbdDraw {
  const Model& m;
  Number num;
  const std::vector<int>& bodies;
  const std::set<ex, ex_is_less>& unknowns;
  Projection proj;
  std::set<std::string> internal;  // a system's internal forces (force_key), not drawn
  std::vector<Pending> pending;
  Figure f;
  std::vector<Drawn> drawn;
  std::vector<std::vector<std::array<double, 3>>> body_points;  // each body's, model units (2-D and 3-D)
  double scale = 1;                                             // model units to drawing units
  std::vector<double> offsets;                                  // each arrow's, sideways, to keep off another arrow

  // Model space onto paper (1-D: the axis vertical when gravity acts along it); a system's
  // forces from outside it only: a connection (or strand) whose loads on the system's bodies
  // add up to nothing is internal to it.
  FbdDraw(const Model& model, Number number, const std::vector<int>& drawn_bodies, bool system,
          const std::set<ex, ex_is_less>& unknown)
      : m(model), num(std::move(number)), bodies(drawn_bodies), unknowns(unknown), body_points(drawn_bodies.size()) {
    proj.dims = m.dims();
    if (proj.dims == 1) {
      proj.axis1 = {1, 0};
      if (m.gravity)
        if (auto g = num((*m.gravity)[0]); g && *g != 0) proj.axis1 = {0, *g < 0 ? 1.0 : -1.0};
    }
    internal = system ? internal_forces(m, bodies) : std::set<std::string>{};
  }

  // A vector of the model's at the layout's numbers, or none.
  std::optional<std::array<double, 3>> point3(const Vec& v) const { return fig::point3(m, num, v); }

  // The arrows of a force vector: one per unknown in it (its coefficient gives the
  // direction), and one per axis for what is known (pointing the way that leaves its label
  // without a minus sign: m g down, not -m g up).
  // The length of a direction written in the parameters and coordinates: sqrt(c.c), with
  // sin^2 + cos^2 = 1 where that leaves fewer terms.
  ex magnitude(const Vec& c) const {
    ex squared = 0;
    for (int k = 0; k < m.dims(); ++k) squared += pow(c[k], 2);
    return sqrt(fewer_trig_terms(squared.expand()));
  }

  void decompose(int body, const Vec& force, std::optional<std::array<double, 3>> at, const ex& factor, bool dashed,
                 bool at_cm) {
    for (const ForcePart& part : split_force(m, force, unknowns, num)) {
      if (!part.unknown.is_zero()) {
        const V d = proj(part.numbers);
        if (len(d) < 1e-9) continue;
        int nonzero = 0, which = 0;
        for (int k = 0; k < m.dims(); ++k)
          if (std::fabs(part.numbers[k]) > 1e-12) {
            ++nonzero;
            which = k;
          }
        // Along a direction of more than one axis, an inertial arrow's size is the unknown
        // times the direction's length: a bar's center moves by L ddot(theta)/2 as its angle
        // turns by ddot(theta), so the arrow is m L ddot(theta)/2. (A force's direction is a
        // unit vector, perhaps written with a string's length: its label is the unknown.)
        ex label = (dashed ? magnitude(part.coefficients) : ex(1)) * part.key * part.unknown;
        if (nonzero == 1)
          label = (part.numbers[which] < 0 ? -part.coefficients[which] : part.coefficients[which]) * part.key *
                  part.unknown;
        const bool push = !dashed && part.key.is_equal(1) && contact_normal(m, part.unknown);
        pending.push_back({body, at, normalized(d), factor * label, dashed, at_cm, push});
        continue;
      }
      for (int k = 0; k < m.dims(); ++k) {
        const ex& rk = part.coefficients[k];
        if (rk.is_zero()) continue;
        const bool negative = to_latex(rk).rfind('-', 0) == 0;
        std::array<double, 3> e{0, 0, 0};
        e[k] = negative ? -1 : 1;
        const V d = proj(e);
        if (len(d) < 1e-9) continue;
        pending.push_back({body, at, normalized(d), factor * (negative ? -rk : rk), dashed, at_cm});
      }
    }
  }

  // Each body's points (2-D and 3-D): its center of mass and where forces act on it; false
  // where one cannot be evaluated.
  bool gather() {
    bool failed = false;
    for (std::size_t i = 0; i < bodies.size(); ++i) {
      const Body& b = m.bodies[bodies[i]];
      if (proj.dims > 1 && b.has_cm) {
        if (auto p = point3(b.cm))
          body_points[i].push_back(*p);
        else
          failed = true;
      }
      for (const auto& l : m.loads)
        if (l.body == bodies[i] && l.at && proj.dims > 1) {
          if (auto p = point3(*l.at))
            body_points[i].push_back(*p);
          else
            failed = true;
        }
    }
    return !failed;
  }

  // Model units to drawing units, for 2-D and 3-D bodies drawn from their points: the
  // bodies body_extent across.
  void choose_scale() {
    if (proj.dims <= 1) return;
    double extent = 0;
    std::vector<V> all;
    for (const auto& pts : body_points)
      for (const auto& p : pts) all.push_back(proj(p));
    for (const V& a : all)
      for (const V& b : all) extent = std::max(extent, len(a - b));
    for (int bi : bodies)
      if (!m.bodies[bi].drawn_size.empty())
        for (const auto& s : m.bodies[bi].drawn_size) extent = std::max(extent, num(s).value_or(0));
    scale = extent > 1e-9 ? body_extent / extent : 1;
  }

  // Outlines: 1-D bodies side by side, the others at their centers of mass (else their
  // first point).
  void outlines() {
    for (std::size_t i = 0; i < bodies.size(); ++i) {
      const Body& b = m.bodies[bodies[i]];
      V centre;
      if (proj.dims == 1) {
        centre = (3.0 * static_cast<double>(i)) * (proj.axis1.x != 0 ? V{1, 0} : V{0, -1});
      } else if (b.has_cm) {
        centre = scale * proj(*point3(b.cm));
      } else if (!body_points[i].empty()) {
        centre = scale * proj(body_points[i].front());
      }
      const Drawn d =
          draw_body(m, bodies[i], body_points[i], proj, scale, num, centre, std::nullopt, particle_side, 0.3);
      f.outlines.push_back(d.outline);
      drawn.push_back(d);
    }
  }

  // The loads on the i-th body from outside the system: its forces to draw, its couples
  // (2-D) as arcs at their points.
  void loads_on(std::size_t i) {
    const int bi = bodies[i];
    for (const auto& l : m.loads) {
      if (l.body != bi || internal.count(force_key(l.origin))) continue;
      std::optional<std::array<double, 3>> at;
      if (l.at && proj.dims > 1) at = point3(*l.at);
      const bool at_cm = l.at && m.bodies[bi].has_cm && is_zero_vec(*l.at - m.bodies[bi].cm);
      decompose(bi, l.force, at, 1, false, at_cm);
      if (proj.dims == 2 && !l.couple[2].is_zero()) {
        FigureCouple c;
        c.centre = fp(at ? scale * proj(*at) : drawn[i].centre);
        auto v = num(l.couple[2]);
        c.counterclockwise = !(v && *v < 0);
        c.label.tex = to_latex(c.counterclockwise ? l.couple[2] : -l.couple[2]);
        f.couples.push_back(c);
      }
    }
  }

  // The i-th body's inertial terms, dashed: m a at its center of mass, and I alpha
  // counterclockwise (the sense the angle is counted in).
  void inertial(std::size_t i) {
    const int bi = bodies[i];
    const Body& b = m.bodies[bi];
    const Vec a = kinematics::acceleration(m, b);
    if (b.has_mass && !b.mass.is_zero() && !is_zero_vec(a)) {
      std::optional<std::array<double, 3>> at;
      if (proj.dims > 1 && b.has_cm) at = point3(b.cm);
      decompose(bi, a, at, b.mass, true, true);
    }
    if (proj.dims == 2 && !b.angle.is_zero() && !b.inertia.is_zero()) {
      const auto q = std::find_if(m.coordinates.begin(), m.coordinates.end(),
                                  [&](const Coordinate& c) { return c.q.is_equal(b.angle); });
      if (q != m.coordinates.end()) {
        FigureCouple c;
        c.centre = fp(drawn[i].centre);
        c.radius = 0.8;
        c.dashed = true;
        c.label.tex = to_latex(b.inertia * q->accel);
        f.couples.push_back(c);
      }
    }
  }

  // Arrows: pushed onto the outline where they press on it, pulling away from it elsewhere;
  // an arrow that would lie on another is moved to one side.
  void arrows() {
    std::vector<std::pair<V, V>> placed;  // tail, head
    std::vector<FigureArrow> made(pending.size());
    offsets.assign(pending.size(), 0);
    // A contact's push is placed last: it is the one moved along its face when it would lie on
    // another arrow (the weight leaves the center of mass down the line it presses up along).
    std::vector<std::size_t> order;
    for (bool push : {false, true})
      for (std::size_t i = 0; i < pending.size(); ++i)
        if (pending[i].push == push) order.push_back(i);
    for (std::size_t i : order) {
      const Pending& p = pending[i];
      const Drawn& d = *std::find_if(drawn.begin(), drawn.end(), [&](const Drawn& x) { return x.body == p.body; });
      const V anchor0 = p.at && !d.particle ? scale * proj(*p.at) : d.centre;
      V tail, head;
      auto make = [&](double offset) {
        const V anchor = anchor0 + offset * perp(p.direction);
        if (p.push) {
          // A contact pushing: from outside, its head on the outline where the body is pressed
          // (the side the force comes from), wherever the model puts the contact's point.
          head = inside(d.outline, anchor) ? exit_point(d.outline, anchor, -1 * p.direction) : anchor;
          tail = head - arrow_length * p.direction;
        } else if ((p.dashed || p.at_cm) && !d.particle) {
          tail = anchor;  // m a and the weight at the center of mass
          head = tail + arrow_length * p.direction;
        } else if (d.particle || !p.at) {
          tail = inside(d.outline, anchor) ? exit_point(d.outline, anchor, p.direction) : anchor;
          head = tail + arrow_length * p.direction;
        } else if (boundary_distance(d.outline, anchor) < 0.05 && dot(p.direction, d.centre - anchor) > 1e-9) {
          head = anchor;  // pressing on the body: drawn from outside, its head at the point
          tail = anchor - arrow_length * p.direction;
        } else {
          tail = anchor;
          head = anchor + arrow_length * p.direction;
        }
      };
      auto clashes = [&] {
        for (const auto& [t, h] : placed) {
          const V u = normalized(h - t);
          if (std::fabs(cross(u, p.direction)) > 0.1) continue;
          if (std::fabs(cross(tail - t, u)) > 0.15) continue;
          const double a0 = dot(tail - t, u), a1 = dot(head - t, u);
          const double lo = std::min(a0, a1), hi = std::max(a0, a1), l = len(h - t);
          if (hi > 0.05 && lo < l - 0.05) return true;
        }
        return false;
      };
      // A push moved aside stays on the outline it presses (off it, its head would be nowhere).
      auto off_outline = [&](double by) {
        return p.push && inside(d.outline, anchor0) && !inside(d.outline, anchor0 + by * perp(p.direction));
      };
      double offset = 0;
      make(0);
      for (int k = 1; k <= 8 && clashes(); ++k) {
        const double by = spacing * ((k + 1) / 2) * (k % 2 ? 1 : -1);
        if (off_outline(by)) continue;
        make(offset = by);
      }
      placed.push_back({tail, head});
      offsets[i] = offset;
      made[i].from = fp(tail);
      made[i].to = fp(head);
      made[i].dashed = p.dashed;
      made[i].label.tex = to_latex(p.label);
    }
    f.arrows.insert(f.arrows.end(), made.begin(), made.end());
  }

  // In 1-D the arrows along one side of a body sit evenly about its middle (two strands
  // under a pulley block to either side of it).
  void centre_sides() {
    if (proj.dims != 1) return;
    std::map<std::pair<int, int>, std::vector<std::size_t>> sides;
    for (std::size_t i = 0; i < pending.size(); ++i)
      sides[{pending[i].body, dot(pending[i].direction, proj.axis1) > 0 ? 1 : -1}].push_back(i);
    for (const auto& [key, members] : sides) {
      double lo = 1e300, hi = -1e300;
      for (std::size_t i : members) {
        lo = std::min(lo, offsets[i]);
        hi = std::max(hi, offsets[i]);
      }
      const double shift = -(lo + hi) / 2;
      for (std::size_t i : members) {
        const V u = pending[i].direction, by = shift * perp(u);
        V tail = vp(f.arrows[i].from) + by, head = vp(f.arrows[i].to) + by;
        // A pull leaving the outline leaves it still where it now is: a strand off a pulley
        // block's rim, not from a point beside it.
        const Drawn& d =
            *std::find_if(drawn.begin(), drawn.end(), [body = key.first](const Drawn& x) { return x.body == body; });
        const V anchor = d.centre + (offsets[i] + shift) * perp(u);
        if (!pending[i].push && boundary_distance(d.outline, vp(f.arrows[i].from)) < 0.05 &&
            inside(d.outline, anchor)) {
          tail = exit_point(d.outline, anchor, u);
          head = tail + arrow_length * u;
        }
        f.arrows[i].from = fp(tail);
        f.arrows[i].to = fp(head);
      }
    }
  }

  // Dots at the named points where forces act (2-D and 3-D), and at each centre of mass.
  void dots() {
    if (proj.dims <= 1) return;
    std::set<std::string> named;
    for (int bi : bodies) {
      for (const auto& l : m.loads)
        if (l.body == bi && l.at && !l.at_name.empty() && !internal.count(force_key(l.origin)) &&
            std::any_of(m.points.begin(), m.points.end(), [&](const Point& p) { return p.name == l.at_name; }) &&
            named.insert(l.at_name).second) {
          FigureDot dot;
          dot.at = fp(scale * proj(*point3(*l.at)));
          FigureLabel name;
          name.tex = default_tex(l.at_name);
          dot.label = name;
          f.dots.push_back(dot);
        }
      if (m.bodies[bi].has_cm) f.dots.push_back({fp(scale * proj(*point3(m.bodies[bi].cm))), std::nullopt});
    }
  }

  // Labels: at the free end of each arrow first (the tail of an arrow pressing on a body,
  // else the head), then beside it; the couples', the named points'.
  void labels() {
    Layout lay(f);
    for (auto& a : f.arrows) {
      const V t = vp(a.from), h = vp(a.to);
      const V u = normalized(h - t), n = perp(u);
      bool pressing = false;
      for (const auto& o : f.outlines) pressing = pressing || boundary_distance(o, h) < 0.06;
      const V end = pressing ? t : h;
      const V out = pressing ? -1 * u : u;
      const double w = char_width * static_cast<double>(shown_length(a.label.tex)) + 0.12;
      const double reach = 0.5 * (std::fabs(out.x) * w + std::fabs(out.y) * label_height) + gap;
      const V mid = 0.5 * (t + h);
      const double side = 0.5 * (std::fabs(n.x) * w + std::fabs(n.y) * label_height) + gap;
      a.label = lay.place(a.label.tex,
                          {end + reach * out, end + side * n, end - side * n, mid + side * n, mid - side * n,
                           end + reach * out + side * n, end + reach * out - side * n, end + (reach + 0.4) * out});
    }
    for (auto& c : f.couples) {
      std::vector<V> cand{vp(c.centre) + V{0, c.radius + 0.3}, vp(c.centre) + V{c.radius + 0.4, 0}};
      for (V dir : {V{-1, 0}, V{0, -1}, V{0.7, 0.7}, V{-0.7, 0.7}, V{0.7, -0.7}, V{-0.7, -0.7}})
        cand.push_back(vp(c.centre) + (c.radius + 0.45) * dir);
      c.label = lay.place(c.label.tex, cand);
    }
    for (auto& d : f.dots)
      if (d.label) {
        const V p = vp(d.at);
        std::vector<V> cand;
        for (const double r : {0.3, 0.55})
          for (V dir : {V{-1, -1}, V{1, -1}, V{-1, 1}, V{1, 1}, V{0, -1}, V{-1, 0}, V{1, 0}, V{0, 1}})
            cand.push_back(p + r * dir);
        d.label = lay.place(d.label->tex, cand);
      }
  }

  // The axes, and the caption naming the bodies ("the system" of more than one drawn as one).
  void close(bool system) {
    std::vector<V> directions;
    for (int k = 0; k < m.dims(); ++k) directions.push_back(normalized(proj.dims == 1 ? proj.axis1 : proj.axis(k)));
    finish(f, directions, m.axes);
    std::vector<std::string> names;
    for (int bi : bodies) names.push_back(m.bodies[bi].name);
    std::string list;
    for (std::size_t i = 0; i < names.size(); ++i)
      list += (i ? (i + 1 == names.size() ? " and " : ", ") : "") + names[i];
    f.caption = std::string("Free body diagram of ") + (system && bodies.size() > 1 ? "the system " : "") + list;
    f.bodies = bodies;
    f.system = system;
  }
};

}  // namespace

namespace fig {

void finish(Figure& f, const std::vector<V>& directions, const std::vector<std::string>& names) {
  settle_labels(f);  // the figure whole: each label clear of everything drawn (figure/labels.hpp)
  // Bounds, then the axes at the lower left, outside everything else.
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
    grow(vp(a.from));
    grow(vp(a.to));
    grow_label(a.label);
    f.arrows.push_back(a);
  }
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
    if (b.drawn_shape == "circle") {
      d.outline.shape = FigureOutline::Shape::circle;
      d.outline.centre = fp(d.centre);
      d.outline.radius = unit * num(b.drawn_size[0]).value_or(1) / 2;
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

std::optional<std::array<double, 3>> point3(const Model& m, const Number& num, const Vec& v) {
  return point_at(m, num, v);
}

}  // namespace fig

// The numbers the geometry is drawn at (layout_numbers), made once per model.
FigureMaker::FigureMaker(const Model& m) : FigureMaker(m, {}) {}

FigureMaker::FigureMaker(const Model& m, const exmap& values)
    : m_(m), values_(layout_numbers(m, values)), unknowns_(m.candidates.begin(), m.candidates.end()) {}

// A number of the geometry, through the evaluation every stage uses (no pole reaches GiNaC);
// none where it is undefined or not real.
std::optional<double> FigureMaker::number(const ex& e) const { return real_at(e, values_); }

std::optional<Figure> FigureMaker::redraw(const Figure& f) const {
  return f.sketch ? sketch() : draw(f.bodies, f.system);
}

std::optional<Figure> free_body_diagram(const Model& m, const std::vector<int>& bodies, bool system) {
  return FigureMaker(m).draw(bodies, system);
}

std::optional<Figure> FigureMaker::draw(const std::vector<int>& bodies, bool system) const {
  PersonOrder order(factor_rank({m_.symbols}));
  FbdDraw s(
      m_, [this](const ex& e) { return number(e); }, bodies, system, unknowns_);
  if (!s.gather()) return std::nullopt;
  s.choose_scale();
  s.outlines();
  for (std::size_t i = 0; i < bodies.size(); ++i) {
    s.loads_on(i);
    s.inertial(i);
  }
  s.arrows();
  s.centre_sides();
  s.dots();
  s.labels();
  s.close(system);
  return s.f;
}

}  // namespace tackle
