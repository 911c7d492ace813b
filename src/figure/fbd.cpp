// Free body diagrams from the model's geometry: outlines, arrows at their points, labels
// placed where nothing else is.
#include <algorithm>
#include <cmath>
#include <functional>
#include <map>
#include <set>

#include "expr/print.hpp"
#include "equations/equations.hpp"
#include "expr/trig.hpp"
#include "figure/figure.hpp"
#include "figure/geometry.hpp"
#include "figure/labels.hpp"
#include "model/forces.hpp"
#include "model/kinematics.hpp"
#include "model/path.hpp"
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

  // A known inertial term across more than one axis whose length is a perfect square's root
  // (a bob's m l dot(theta)^2 towards its pin): one arrow along it, as the book draws it,
  // labelled with its length. False where it is not one (the axes' components drawn instead).
  bool along_one_line(int body, const Vec& c, std::optional<std::array<double, 3>> at, const ex& factor, bool at_cm) {
    int across = 0;
    for (int k = 0; k < m.dims(); ++k) across += !c[k].is_zero();
    if (across < 2) return false;
    ex squared = 0;
    for (int k = 0; k < m.dims(); ++k) squared += pow(c[k], 2);
    squared = squared.expand();
    std::optional<ex> root;
    for (const ex& form : {squared, fewer_trig_terms(squared), pythagoras(squared, true), pythagoras(squared, false)})
      if ((root = square_root_of(form))) break;
    if (!root) return false;
    // Its sign where the rates are not given at the layout's numbers: a length even in every
    // rate (dot(theta)^2) has the sign it has with the rates at 1.
    exmap at_one, turned;
    for (const Coordinate& q : m.coordinates) {
      at_one[q.rate] = 1;
      turned[q.rate] = -q.rate;
    }
    if (!(root->subs(turned) - *root).expand().is_zero()) return false;
    const auto value = num(root->subs(at_one));
    if (!value || std::fabs(*value) < 1e-12) return false;
    const ex length = *value < 0 ? -*root : *root;
    Vec unit = zero_vec();
    for (int k = 0; k < m.dims(); ++k) unit[k] = normal(c[k] / length);
    const auto numbers = point3(unit);
    if (!numbers || len(proj(*numbers)) < 1e-9) return false;
    pending.push_back({body, at, normalized(proj(*numbers)), factor * length, true, at_cm});
    return true;
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
      if (dashed && along_one_line(body, part.coefficients, at, factor, at_cm)) continue;
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
      // A particle's forces act at its center (a block under a block: the push at the upper
      // one's center is a push on its top face): it is drawn as a block, not the box of
      // points out to the other's center.
      if (proj.dims > 1 && particle(m, bodies[i])) continue;
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

  // The blocks resting on a face (a block on a wedge), turned along it (figure/contacts.cpp).
  std::map<int, V> along_faces() const {
    std::map<int, V> along;
    if (proj.dims != 2) return along;
    std::vector<std::vector<std::array<double, 3>>> centres(m.bodies.size());
    for (std::size_t b = 0; b < m.bodies.size(); ++b)
      if (m.bodies[b].has_cm)
        if (auto p = point3(m.bodies[b].cm)) centres[b].push_back(*p);
    for (const Resting& r : resting(m, num, proj, centres)) along.emplace(r.rider, face_way(r.normal));
    return along;
  }

  // Outlines: 1-D bodies side by side, the others at their centers of mass (else their
  // first point).
  void outlines() {
    const std::map<int, V> along = along_faces();
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
      const auto a = along.find(bodies[i]);
      const Drawn d = draw_body(m, bodies[i], body_points[i], proj, scale, num, centre,
                                a == along.end() ? std::nullopt : std::optional<V>(a->second), particle_side, 0.3);
      f.outlines.push_back(d.outline);
      draw_hub(f, d);
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
        // From a point inside the body (its center of mass, a pin at a disk's center), long
        // enough to leave it: the head and its label outside the outline.
        if (!p.push && !d.particle && inside(d.outline, tail))
          head =
              tail + std::max(arrow_length, len(exit_point(d.outline, tail, p.direction) - tail) + 0.7) * p.direction;
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

  // Dots at the named points where forces act (2-D and 3-D), and at each centre of mass; not
  // on a body drawn around one point (a bob: its forces drawn at it, not at a pin away from it).
  void dots() {
    if (proj.dims <= 1) return;
    std::set<std::string> named;
    for (std::size_t i = 0; i < bodies.size(); ++i) {
      const int bi = bodies[i];
      for (const auto& l : m.loads)
        if (l.body == bi && !drawn[i].particle && l.at && !l.at_name.empty() && !internal.count(force_key(l.origin)) &&
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

  // The mass-times-acceleration diagram beside the free body diagram, as the book draws the
  // two (the forces on the left equal m a_G and I alpha on the right): the bodies again, past
  // an equals sign, m a_G from each center of mass (one arrow per unknown, the known part by
  // axes) and I alpha as a dashed arc about it. None where nothing accelerates (statics).
  void kinetic() {
    Figure forces = std::move(f);
    f = Figure{};
    f.outlines = forces.outlines;
    for (const Drawn& d : drawn) draw_hub(f, d);
    pending.clear();
    for (std::size_t i = 0; i < bodies.size(); ++i) inertial(i);
    if (pending.empty() && f.couples.empty()) {
      f = std::move(forces);
      return;
    }
    double middle = 0;
    for (const Drawn& d : drawn) {
      middle += d.centre.y / static_cast<double>(drawn.size());
      if (proj.dims > 1 && m.bodies[d.body].has_cm) f.dots.push_back({fp(d.centre), std::nullopt});
    }
    arrows();
    labels();
    measure(forces);
    measure(f);
    const double room = 1.2;  // between the two diagrams, the equals sign in its middle
    const V by{forces.max_x - f.min_x + room, 0};
    shift(f, by);
    FigureLabel equals;
    equals.tex = "=";
    equals.width = char_width + 0.12;
    equals.height = label_height;
    equals.at = fp({forces.max_x + room / 2, middle});
    forces.texts.push_back(equals);
    append(forces, f);
    f = std::move(forces);
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
  for (std::size_t i = 0; i < bodies.size(); ++i) s.loads_on(i);
  s.arrows();
  s.centre_sides();
  s.dots();
  s.labels();
  s.kinetic();
  s.close(system);
  return s.f;
}

}  // namespace tackle
