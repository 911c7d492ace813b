// The plane geometry the figures share (internal to src/figure/): points on paper, outlines,
// and the greedy placement of labels where nothing else is drawn.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <functional>
#include <map>
#include <set>
#include <optional>
#include <string>
#include <vector>

#include "figure/figure.hpp"

namespace tackle::fig {

struct V {
  double x = 0, y = 0;
};
inline V operator+(V a, V b) { return {a.x + b.x, a.y + b.y}; }
inline V operator-(V a, V b) { return {a.x - b.x, a.y - b.y}; }
inline V operator*(double s, V a) { return {s * a.x, s * a.y}; }
inline double dot(V a, V b) { return a.x * b.x + a.y * b.y; }
inline double cross(V a, V b) { return a.x * b.y - a.y * b.x; }
inline double len(V a) { return std::hypot(a.x, a.y); }
inline V normalized(V a) { return (1 / len(a)) * a; }
inline V perp(V a) { return {-a.y, a.x}; }
inline FigurePoint fp(V a) { return {a.x, a.y}; }
inline V vp(FigurePoint a) { return {a.x, a.y}; }

// Sizes in drawing units (about centimetres).
constexpr double body_extent = 3.2;    // the largest drawn body
constexpr double particle_side = 1.2;  // a body drawn around one point
constexpr double arrow_length = 1.2;
constexpr double spacing = 0.38;  // between parallel arrows that would overlap
constexpr double char_width = 0.2, label_height = 0.42, gap = 0.1;
constexpr double label_spacing = 0.06;  // kept between two labels' boxes

inline bool inside(const FigureOutline& o, V p) {
  if (o.shape == FigureOutline::Shape::circle) return len(p - vp(o.centre)) < o.radius;
  bool in = false;
  const auto& c = o.corners;
  for (std::size_t i = 0, j = c.size() - 1; i < c.size(); j = i++) {
    if ((c[i].y > p.y) != (c[j].y > p.y) && p.x < (c[j].x - c[i].x) * (p.y - c[i].y) / (c[j].y - c[i].y) + c[i].x)
      in = !in;
  }
  return in;
}

inline double segment_distance(V p, V a, V b) {
  const V ab = b - a;
  const double l2 = dot(ab, ab);
  const double t = l2 == 0 ? 0 : std::clamp(dot(p - a, ab) / l2, 0.0, 1.0);
  return len(p - (a + t * ab));
}

inline double boundary_distance(const FigureOutline& o, V p) {
  if (o.shape == FigureOutline::Shape::circle) return std::fabs(len(p - vp(o.centre)) - o.radius);
  double d = 1e300;
  for (std::size_t i = 0; i < o.corners.size(); ++i)
    d = std::min(d, segment_distance(p, vp(o.corners[i]), vp(o.corners[(i + 1) % o.corners.size()])));
  return d;
}

// Where the ray from p along u leaves the outline (p inside it).
inline V exit_point(const FigureOutline& o, V p, V u) {
  double lo = 0, hi = 4 * body_extent;
  for (int i = 0; i < 40; ++i) {
    const double mid = (lo + hi) / 2;
    (inside(o, p + mid * u) ? lo : hi) = mid;
  }
  return p + hi * u;
}

inline std::vector<FigurePoint> convex_hull(std::vector<V> p) {
  std::sort(p.begin(), p.end(), [](V a, V b) { return a.x < b.x || (a.x == b.x && a.y < b.y); });
  std::vector<V> h(2 * p.size());
  std::size_t k = 0;
  for (std::size_t i = 0; i < p.size(); ++i) {
    while (k >= 2 && cross(h[k - 1] - h[k - 2], p[i] - h[k - 2]) <= 0) --k;
    h[k++] = p[i];
  }
  for (std::size_t i = p.size() - 1, t = k + 1; i > 0; --i) {
    while (k >= t && cross(h[k - 1] - h[k - 2], p[i - 1] - h[k - 2]) <= 0) --k;
    h[k++] = p[i - 1];
  }
  h.resize(k > 1 ? k - 1 : k);
  std::vector<FigurePoint> out;
  for (V v : h) out.push_back(fp(v));
  return out;
}

inline FigureOutline rectangle(V centre, V along, double w, double h) {
  const V u = normalized(along), n = perp(u);
  FigureOutline o;
  for (auto [a, b] : {std::pair{-1, -1}, {1, -1}, {1, 1}, {-1, 1}})
    o.corners.push_back(fp(centre + (a * w / 2) * u + (b * h / 2) * n));
  return o;
}

/// v turned by a (radians, counterclockwise).
inline V rotate(V v, double a) {
  return {std::cos(a) * v.x - std::sin(a) * v.y, std::sin(a) * v.x + std::cos(a) * v.y};
}

/// Where the ray from p along u first reaches the outline's edge (p inside it).
inline V leave(const FigureOutline& o, V p, V u) { return inside(o, p) ? exit_point(o, p, u) : p; }

/// How far the outline reaches from p along u (0 when it does not reach past p).
inline double reach_along(const FigureOutline& o, V p, V u) {
  if (o.shape == FigureOutline::Shape::circle) return std::max(0.0, dot(vp(o.centre) - p, u) + o.radius);
  double r = 0;
  for (const auto& c : o.corners) r = std::max(r, dot(vp(c) - p, u));
  return r;
}

/// The outline's extent along u: [lo, hi] of dot(x, u) over it.
/// Along a face whose normal is `n` (unit, on paper): to the right, else up.
inline V face_way(V n) {
  const V t = perp(n);
  return t.x < -1e-9 || (std::fabs(t.x) <= 1e-9 && t.y < 0) ? -1 * t : t;
}

inline std::pair<double, double> extent_along(const FigureOutline& o, V u) {
  if (o.shape == FigureOutline::Shape::circle)
    return {dot(vp(o.centre), u) - o.radius, dot(vp(o.centre), u) + o.radius};
  double lo = 1e300, hi = -1e300;
  for (const auto& c : o.corners) {
    lo = std::min(lo, dot(vp(c), u));
    hi = std::max(hi, dot(vp(c), u));
  }
  return {lo, hi};
}

/// An arc of radius r about c from angle a0 to a1 (radians, counterclockwise when a1 > a0).
inline std::vector<FigurePoint> arc(V c, double r, double a0, double a1) {
  std::vector<FigurePoint> out;
  const int n = std::max(2, static_cast<int>(std::fabs(a1 - a0) / 0.15) + 1);
  for (int i = 0; i <= n; ++i) {
    const double a = a0 + (a1 - a0) * i / n;
    out.push_back(fp(c + r * V{std::cos(a), std::sin(a)}));
  }
  return out;
}

struct Box {
  V c;
  double w, h;
};
inline bool overlaps(const Box& a, const Box& b) {
  return std::fabs(a.c.x - b.c.x) * 2 < a.w + b.w && std::fabs(a.c.y - b.c.y) * 2 < a.h + b.h;
}
// Whether the segment p-q passes through the box (Liang-Barsky clipping).
inline bool box_hits_segment(const Box& b, V p, V q) {
  double t0 = 0, t1 = 1;
  const V d = q - p;
  const double lo[2] = {b.c.x - b.w / 2, b.c.y - b.h / 2}, hi[2] = {b.c.x + b.w / 2, b.c.y + b.h / 2};
  const double s[2] = {p.x, p.y}, ds[2] = {d.x, d.y};
  for (int k = 0; k < 2; ++k) {
    if (std::fabs(ds[k]) < 1e-12) {
      if (s[k] <= lo[k] || s[k] >= hi[k]) return false;
      continue;
    }
    double a = (lo[k] - s[k]) / ds[k], c = (hi[k] - s[k]) / ds[k];
    if (a > c) std::swap(a, c);
    t0 = std::max(t0, a);
    t1 = std::min(t1, c);
    if (t0 >= t1) return false;
  }
  return true;
}

class Layout {
 public:
  // On an arrow: worse than lying in an outline across its edges.
  static constexpr double arrow_penalty = 40;

  explicit Layout(Figure& f) : f_(f) {}

  // A label tried at the candidate centres in order; the first that touches nothing wins,
  // else the one that touches least. Where every candidate lies on another label or on an
  // arrow, rings of places farther out around the first are tried too.
  FigureLabel place(const std::string& tex, const std::vector<V>& candidates) {
    FigureLabel l;
    l.tex = tex;
    l.width = char_width * static_cast<double>(shown_length(tex)) + 0.12;
    l.height = label_height;
    double best = 1e300;
    V at = candidates.front();
    auto consider = [&](V c, double cost) {
      const double p = penalty({c, l.width, l.height}) + cost;
      if (p < best) {
        best = p;
        at = c;
      }
    };
    for (std::size_t i = 0; i < candidates.size(); ++i) consider(candidates[i], 0.01 * static_cast<double>(i));
    for (int ring = 1; ring <= 6 && best >= arrow_penalty; ++ring)
      for (int k = 0; k < 16; ++k) {
        const double a = 2 * M_PI * k / 16, r = 0.3 * ring;
        consider(candidates.front() + V{(r + l.width / 2) * std::cos(a), (r + l.height / 2) * std::sin(a)},
                 1 + 0.1 * ring);
      }
    l.at = fp(at);
    boxes_.push_back({at, l.width, l.height});
    return l;
  }

 private:
  double penalty(const Box& b) const {
    double p = 0;
    // Labels a little apart (a subscript close above the next label reads as its own).
    const Box roomy{b.c, b.w + label_spacing, b.h + label_spacing};
    for (const auto& o : boxes_)
      if (overlaps(roomy, o)) p += 100;
    for (const auto& a : f_.arrows)
      if (box_hits_segment(b, vp(a.from), vp(a.to))) p += arrow_penalty;
    for (const auto& l : f_.lines)
      for (std::size_t i = 1; i < l.points.size(); ++i)
        if (box_hits_segment(b, vp(l.points[i - 1]), vp(l.points[i]))) p += l.thin ? 3 : 10;
    for (const auto& t : f_.texts)
      if (overlaps(b, {vp(t.at), t.width, t.height})) p += 100;
    for (const auto& o : f_.outlines) {
      for (V c : {b.c, b.c + V{b.w / 2, b.h / 2}, b.c + V{-b.w / 2, b.h / 2}, b.c + V{b.w / 2, -b.h / 2},
                  b.c + V{-b.w / 2, -b.h / 2}})
        if (inside(o, c)) p += 3;
      if (o.shape == FigureOutline::Shape::polygon)
        for (std::size_t i = 0; i < o.corners.size(); ++i)
          if (box_hits_segment(b, vp(o.corners[i]), vp(o.corners[(i + 1) % o.corners.size()]))) p += 5;
    }
    for (const auto& d : f_.dots)
      if (std::fabs(d.at.x - b.c.x) * 2 < b.w + 0.1 && std::fabs(d.at.y - b.c.y) * 2 < b.h + 0.1) p += 10;
    // A couple's arc (from -60 to 240 degrees, as it is drawn), in short chords.
    for (const auto& c : f_.couples)
      for (int k = 0; k < 10; ++k) {
        const double a0 = (-60.0 + 30.0 * k) * M_PI / 180, a1 = (-60.0 + 30.0 * (k + 1)) * M_PI / 180;
        const V centre = vp(c.centre);
        if (box_hits_segment(b, centre + c.radius * V{std::cos(a0), std::sin(a0)},
                             centre + c.radius * V{std::cos(a1), std::sin(a1)})) {
          p += 10;
          break;
        }
      }
    return p;
  }
  Figure& f_;
  std::vector<Box> boxes_;
};

// Model space to the drawing plane: 1-D along the axis (vertical when gravity acts along
// it), 2-D as is, 3-D in an oblique view (x towards the viewer, y to the right, z up).
struct Projection {
  int dims = 2;
  V axis1{1, 0};    // 1-D: the axis' direction on paper
  double turn = 0;  // 2-D: the plane turned by this angle (a sketch turns it so that gravity points down)
  [[nodiscard]] V operator()(const std::array<double, 3>& p) const {
    if (dims == 1) return p[0] * axis1;
    if (dims == 2)
      return {std::cos(turn) * p[0] - std::sin(turn) * p[1], std::sin(turn) * p[0] + std::cos(turn) * p[1]};
    return {p[1] - 0.5 * p[0], p[2] - 0.35 * p[0]};
  }
  [[nodiscard]] V axis(int k) const {
    std::array<double, 3> e{0, 0, 0};
    e[k] = 1;
    return (*this)(e);
  }
};

// A body as drawn: its outline and how forces attach to it.
struct Drawn {
  int body = -1;
  FigureOutline outline;
  V centre;               // on paper
  bool particle = false;  // forces start on its outline, along their line through the centre
  double hub = 0;         // a spool's hub: its radius, on paper (0: none)
};

/// The lines a drawn body adds to its outline: a spool's hub.
inline void draw_hub(Figure& f, const Drawn& d) {
  if (d.hub > 0) f.lines.push_back({arc(d.centre, d.hub, 0, 2 * M_PI), false});
}

// A number of the model's geometry at the layout's numbers, or none.
using Number = std::function<std::optional<double>(const GiNaC::ex&)>;

// A vector of the model's at the layout's numbers (0 beyond its axes), or none.
[[nodiscard]] std::optional<std::array<double, 3>> point3(const Model& m, const Number& num, const Vec& v);

/// Whether unknown `u` is a contact's normal force: its rule holds it at u >= 0 and says the
/// contact pushes or presses ("the contact pushes", "the bodies press on each other", "the
/// wheel presses on the ground"; a string's T >= 0 is "taut": a pull). (figure/contacts.cpp)
[[nodiscard]] bool contact_normal(const Model& m, const GiNaC::ex& u);

/// Two bodies pressing on each other through their centers: a contact between them whose
/// normal force is a contact_normal, its normal along the line of their centers on paper (a
/// block on a block). `d`: the centers' distance on paper in model units; `height`: the share
/// of a block's side that spans it (0.8, its height, when one is above the other; else 1).
struct Stacked {
  int a, b;
  double d, height;
};
/// The stacked pairs of the model at its numbers; `body_points[b]` starts with body b's center.
[[nodiscard]] std::vector<Stacked> stacked(const Model& m, const Number& num, const Projection& proj,
                                           const std::vector<std::vector<std::array<double, 3>>>& body_points);

/// A block resting on a face of a body drawn with its own shape (a block on a wedge): a
/// contact between them whose normal force is a contact_normal, not through both centers.
/// `normal`: on paper, the way the base pushes the rider. The figures turn the rider along
/// the face, and the sketch sets it on the face.
struct Resting {
  int rider, base;
  V normal;
};
[[nodiscard]] std::vector<Resting> resting(const Model& m, const Number& num, const Projection& proj,
                                           const std::vector<std::vector<std::array<double, 3>>>& body_points);

/// A body's outline, as the free body diagrams and the sketches draw it: its own shape
/// (`draw:`) turned by its angle, a small disk for a turning particle (a pendulum's bob), a
/// block `side` wide around a body whose `points` (model units: its center of mass and where
/// forces act on it) are one (turned `along` its line, else along its acceleration), else
/// a bar, plate or box through its points. `centre` is where it is on paper; `scale` turns
/// model units into drawing units; a rod or bar reaches `overhang` beyond its end points in
/// all (a free body diagram's 0.3: no force at an end runs along an edge; a sketch's 0).
[[nodiscard]] Drawn draw_body(const Model& m, int body, const std::vector<std::array<double, 3>>& points,
                              const Projection& proj, double scale, const Number& num, V centre, std::optional<V> along,
                              double side, double overhang);

constexpr double support_width = 1.0;              // a pin's or an anchor's piece of ground
constexpr double pin_drop = 0.45;                  // a pin support's triangle, from the pin to its base
constexpr V down{0, -1};                           // down the page (gravity's way, in a sketch)
constexpr double hatch = 0.22, hatch_step = 0.25;  // the ground's hatching: its strokes and their spacing

/// A strand from p to q as a sketch draws it: a spring's coils (across `across`), a damper's
/// dashpot, else a straight line (a string).
void draw_strand(Figure& f, const std::string& as, V p, V q, V across);
/// The ground along a to b: a line, hatched towards `into` (a unit vector).
void draw_ground(Figure& f, V a, V b, V into);

/// An arrow's label at its free end (its tail where the arrow presses on something, else its
/// head), else beside its middle.
inline FigureLabel place_at_end(Layout& lay, const FigureArrow& a, bool pressing) {
  const V t = vp(a.from), h = vp(a.to), u = normalized(h - t), n = perp(u);
  const double w = char_width * static_cast<double>(shown_length(a.label.tex)) + 0.12;
  const double out = 0.5 * (std::fabs(u.x) * w + std::fabs(u.y) * label_height) + gap;
  const double beside = 0.5 * (std::fabs(n.x) * w + std::fabs(n.y) * label_height) + gap;
  const V end = pressing ? t : h, way = pressing ? -1 * u : u;
  return lay.place(a.label.tex, {end + out * way, 0.5 * (t + h) + beside * n, 0.5 * (t + h) - beside * n});
}

/// The ground that holds a pin at `p` (on paper) of a body whose center is `below_of`: a
/// hanger up to a hatched ceiling when the body hangs below it (above a disk it is in), else
/// the book's triangle on hatched ground.
void draw_support(Figure& f, V p, V below_of);
/// An incline from `foot` to `top` (on paper; its ground below it, `n` its upward normal) as
/// the book draws it: a triangle on hatched ground, the bodies drawn so far in front of it; up
/// to its top, or short of a body beside it that does not rest on it (a block hanging by the
/// top), the rest of the slope hatched. False (nothing drawn) where that would leave less
/// than half of it.
bool draw_incline(Figure& f, V n, V foot, V top, const std::vector<std::optional<Drawn>>& drawn);
/// A wheel (a `wheel` sketch: a car's) touching the ground at `contact` (on paper), `n` the
/// ground's normal: a small disk on the ground.
constexpr double wheel_radius = 0.3;
void draw_wheel(Figure& f, V contact, V n);
/// At each pulley's point (of `pulleys`): the sum of the directions its strands leave in.
[[nodiscard]] std::map<int, V> strands_at(const Model& m, const std::set<int>& pulleys,
                                          const std::function<V(int)>& paper);
/// Where a block resting on a face (Resting) is drawn: its center moved along the face's
/// normal until its side lies on the base's outline.
[[nodiscard]] V on_face(const FigureOutline& base, const Drawn& rider, V normal);

/// Sets the figure's bounds to everything drawn in it, labels included.
void measure(Figure& f);
/// Moves everything drawn in the figure by `by`.
void shift(Figure& f, V by);
/// Draws `more` into `f` (over it, in the same units).
void append(Figure& f, const Figure& more);
/// Bounds of everything drawn, then the axes at the lower left, outside it: `directions`
/// are the axes' directions on paper, `names` their names.
void finish(Figure& f, const std::vector<V>& directions, const std::vector<std::string>& names);

}  // namespace tackle::fig
