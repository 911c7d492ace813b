// The sketch of a 2-D mechanism, from its geometry at the layout's numbers and turned so that
// gravity points down the page: the bodies, the ground they touch, pins and supports,
// pulleys, strings, cables, rods, springs and dampers, applied forces and couples, the angles
// that parameters give, the named points and the axes. Nothing is drawn where a position
// cannot be evaluated.
#include <algorithm>
#include <cmath>
#include <map>
#include <set>

#include "expr/print.hpp"
#include "figure/figure.hpp"
#include "figure/geometry.hpp"

namespace tackle {

using namespace GiNaC;
using namespace fig;

namespace {

constexpr double sketch_extent = 6.0;  // the mechanism's largest extent on paper
constexpr double largest_body = 3.5;   // and its largest body's, at most
constexpr double pulley_radius = 0.25;
constexpr double surface_margin = 0.6;  // the ground beyond the bodies on it
constexpr double lane = 0.3;            // a spring and a damper side by side, this far apart

// A ground surface: the line of points x with dot(x, n) = offset, from lo to hi along
// t = perp(n); the ground is on the side away from n.
struct Surface {
  V n;
  double offset, lo, hi;
  std::vector<ex> geometry;  // what its direction is made of (the normal as written)
};

// An angle to mark: at `vertex`, from the ray along `from` to the ray along `to` (unit
// vectors), `reference` drawn along `from` when it is not already a drawn line.
struct Mark {
  V vertex, from, to;
  double angle;
  std::vector<ex> geometry;
  bool reference;
};

// The steps of a 2-D sketch and what they share: the model at the layout's numbers turned
// onto the page, the bodies as drawn, the ground, pins and pulleys found so far, and the
// figure they draw into. Each step adds to the figure in the story's order.
struct PlaneSketch {
  const Model& m;
  Number num;
  Projection proj;
  std::vector<std::optional<V>> point_at;                        // a point's position turned onto the page, once asked
  std::vector<std::vector<std::array<double, 3>>> body_points;   // a body's center of mass and points of application
  double scale = 1;                                              // model units to drawing units
  double side = particle_side;                                   // a block's side
  std::vector<Stacked> touching;                                 // blocks pressing on each other (choose_scale)
  std::map<int, V> along;                                        // a block turned along the surface it is on
  std::vector<std::pair<const Model::Drawing*, V>> surfaces_of;  // each surface a body touches, its normal on paper
  Figure f;
  std::vector<std::optional<Drawn>> drawn;
  std::set<int> pulleys, held;  // points: a pulley's; a pin's, a surface's (no anchor drawn there)
  std::vector<Mark> marks;
  std::vector<Surface> surfaces;
  std::set<int> dotted;
  std::set<int> pinned;                            // of the dotted: pins and hinges (drawn open)
  std::vector<std::pair<int, V>> wheels;           // a wheel's point on the ground, and the ground's normal
  std::vector<std::pair<const Mark*, ex>> marked;  // the angles marked, with the symbol each is named by

  // Turned so that gravity points down the page.
  PlaneSketch(const Model& model, Number number)
      : m(model),
        num(std::move(number)),
        point_at(model.points.size()),
        body_points(model.bodies.size()),
        drawn(model.bodies.size()) {
    proj.dims = 2;
    if (m.gravity) {
      const auto gx = num((*m.gravity)[0]), gy = num((*m.gravity)[1]);
      if (gx && gy && std::hypot(*gx, *gy) > 1e-12) proj.turn = -M_PI / 2 - std::atan2(*gy, *gx);
    }
  }

  // A point's position in model units turned onto the page (none where it cannot be evaluated).
  std::optional<V> point(int p) {
    if (!point_at[p])
      if (auto q = point3(m, num, m.points[p].position)) point_at[p] = proj(*q);
    return point_at[p];
  }

  // A point's place on paper (one that could be evaluated).
  V paper(int p) { return scale * *point(p); }

  // Whether a point is the ground's.
  bool fixed(int p) const { return m.points[p].body < 0; }

  // Every position the sketch uses, in model units turned onto the page, into `all`: the points
  // of the drawings and each body's center of mass and points of application; false where one
  // cannot be evaluated.
  bool gather(std::vector<V>& all) {
    for (const auto& d : m.drawings) {
      std::vector<int> used = d.path;
      used.insert(used.end(), d.points.begin(), d.points.end());
      if (d.point >= 0) used.push_back(d.point);
      for (int p : used) {
        if (!point(p)) return false;
        all.push_back(*point(p));
      }
    }
    for (std::size_t b = 0; b < m.bodies.size(); ++b) {
      if (m.bodies[b].has_cm) {
        auto p = point3(m, num, m.bodies[b].cm);
        if (!p) return false;
        body_points[b].push_back(*p);
      }
      for (const auto& l : m.loads)
        if (l.body == static_cast<int>(b) && l.at) {
          // (A force at a point of another body, a contact between two bodies, does not make
          // this one reach there: the cart under a block is not drawn up to the block's point.)
          const auto named =
              std::find_if(m.points.begin(), m.points.end(), [&](const Point& x) { return x.name == l.at_name; });
          if (named != m.points.end() && named->body >= 0 && named->body != static_cast<int>(b)) continue;
          auto p = point3(m, num, *l.at);
          if (!p) return false;
          body_points[b].push_back(*p);
        }
      for (const auto& p : body_points[b]) all.push_back(proj(p));
    }
    return true;
  }

  // The scale: the mechanism sketch_extent across, and no body larger than largest_body (the
  // outlines drawn at that scale, measured); blocks pressing on each other touch.
  void choose_scale(const std::vector<V>& all) {
    double extent = 0;
    for (const V& a : all)
      for (const V& b : all) extent = std::max(extent, len(a - b));
    for (const auto& b : m.bodies)
      for (const auto& s : b.drawn_size) extent = std::max(extent, num(s).value_or(0));
    scale = extent > 1e-9 ? sketch_extent / extent : 1;
    double largest = 0;
    for (std::size_t b = 0; b < m.bodies.size(); ++b)
      if (!body_points[b].empty()) {
        const FigureOutline o = draw_body(m, static_cast<int>(b), body_points[b], proj, scale, num,
                                          scale * proj(body_points[b].front()), std::nullopt, particle_side, 0)
                                    .outline;
        const auto [x0, x1] = extent_along(o, V{1, 0});
        const auto [y0, y1] = extent_along(o, V{0, 1});
        largest = std::max({largest, x1 - x0, y1 - y0});
      }
    if (largest > largest_body) scale *= std::max(largest_body / largest, particle_side / largest);
    touching = stacked(m, num, proj, body_points);
    for (const auto& t : touching) scale = std::min(scale, t.height * particle_side / t.d);
  }

  // A block's side: no wider than most of the distance between two bodies, but for blocks
  // pressing on each other, which span theirs.
  void choose_side() {
    auto is_touching = [&](std::size_t a, std::size_t b) {
      return std::any_of(touching.begin(), touching.end(), [&](const Stacked& t) {
        return std::min(t.a, t.b) == static_cast<int>(a) && std::max(t.a, t.b) == static_cast<int>(b);
      });
    };
    double closest = 1e300;
    for (std::size_t a = 0; a < m.bodies.size(); ++a)
      for (std::size_t b = a + 1; b < m.bodies.size(); ++b)
        if (!body_points[a].empty() && !body_points[b].empty() && !is_touching(a, b)) {
          const double d = scale * len(proj(body_points[a][0]) - proj(body_points[b][0]));
          if (d > 1e-6) closest = std::min(closest, d);
        }
    side = std::clamp(0.6 * closest, 0.5, particle_side);
    for (const auto& t : touching) side = std::min(side, std::max(scale * t.d / t.height, 0.3));
  }

  // The normal of each surface a body touches, on paper, and the block on it turned along it;
  // false where a normal cannot be evaluated.
  bool surface_normals() {
    for (const auto& d : m.drawings) {
      if ((d.as != "surface" && d.as != "wheel") || d.body < 0 || d.point < 0) continue;
      const auto n = point3(m, num, d.vector);
      if (!n || len(proj(*n)) < 1e-12) return false;
      const V u = normalized(proj(*n));
      surfaces_of.push_back({&d, u});
      if (d.as == "wheel") wheels.push_back({d.point, u});
      along.emplace(d.body, face_way(u));
    }
    return true;
  }

  // Bodies: each outline at its place, its wheels over it; a turning particle (a pendulum's bob)
  // hangs from the farthest point that holds it.
  void draw_bodies() {
    const std::vector<Resting> rests = resting(m, num, proj, body_points);
    for (const Resting& r : rests) along.emplace(r.rider, face_way(r.normal));
    auto draw_at = [&](std::size_t b, V centre) {
      const auto a = along.find(static_cast<int>(b));
      drawn[b] = draw_body(m, static_cast<int>(b), body_points[b], proj, scale, num, centre,
                           a == along.end() ? std::nullopt : std::optional<V>(a->second), side, 0);
    };
    for (std::size_t b = 0; b < m.bodies.size(); ++b)
      if (!body_points[b].empty()) draw_at(b, scale * proj(body_points[b].front()));  // else nowhere: not drawn
    // A block resting on a face (a block on a wedge) sits on it: its center moved along the
    // face's normal until its side lies on the face.
    for (const Resting& r : rests) {
      draw_at(static_cast<std::size_t>(r.rider), on_face(drawn[r.base]->outline, *drawn[r.rider], r.normal));
    }
    for (std::size_t b = 0; b < m.bodies.size(); ++b) {
      if (!drawn[b]) continue;
      const Body& body = m.bodies[b];
      const V centre = drawn[b]->centre;
      f.outlines.push_back(drawn[b]->outline);
      draw_hub(f, *drawn[b]);
      if (body.drawn_shape.empty() && !body.angle.is_zero() && body.inertia.is_zero()) {
        // Its rod (or string) to the farthest point that holds it: its own, or a pin of
        // another body (the cart's P).
        V far = centre;
        std::vector<V> holders;
        for (const auto& p : body_points[b]) holders.push_back(scale * proj(p));
        for (const auto& l : m.loads)
          if (l.body == static_cast<int>(b) && l.at)
            if (auto p = point3(m, num, *l.at)) holders.push_back(scale * proj(*p));
        for (const V& p : holders)
          if (len(p - centre) > len(far - centre)) far = p;
        if (len(far - centre) > drawn[b]->outline.radius)
          f.lines.push_back({{fp(far), fp(centre + drawn[b]->outline.radius * normalized(far - centre))}, false});
      }
    }
    for (const auto& [p, n] : wheels) draw_wheel(f, paper(p), n);
  }

  // The drawn body a point belongs to, if any.
  const Drawn* body_of(int p) const {
    const int b = m.points[p].body;
    return b >= 0 && drawn[b] ? &*drawn[b] : nullptr;
  }

  // The points of the pulleys, and those a pin or a surface holds (no anchor drawn there).
  void note_pulleys_and_pins() {
    for (const auto& d : m.drawings) {
      if (d.as == "pulley" && d.point >= 0) pulleys.insert(d.point);
      if ((d.as == "pin" || d.as == "joint" || d.as == "surface" || d.as == "wheel") && d.point >= 0)
        held.insert(d.point);
    }
  }

  // The ground the bodies touch: through each contact point (moved along the normal to the
  // body's edge where the point is inside it, as a block's center is), across the normal,
  // under the body and on to the fixed points and the origin on the same line.
  void collect_surfaces() {
    for (const auto& surface_of : surfaces_of) {
      // (Not a structured binding: clang 14 does not let a lambda capture one.)
      const auto& dp = surface_of.first;
      const auto& n = surface_of.second;
      const Model::Drawing& d = *dp;
      const V c = paper(d.point);
      const V t = perp(n);
      const Drawn* body = drawn[d.body] ? &*drawn[d.body] : nullptr;
      const double below = body ? reach_along(body->outline, c, -1 * n) : 0;
      const V on = c - (below > 0.05 ? below : 0) * n;
      double lo = dot(on, t) - surface_margin, hi = dot(on, t) + surface_margin;
      if (body) {
        const auto [a, b] = extent_along(body->outline, t);
        lo = std::min(lo, a - surface_margin);
        hi = std::max(hi, b + surface_margin);
      }
      std::vector<std::pair<V, double>> ends{{V{0, 0}, 0}};  // the origin
      for (std::size_t p = 0; p < m.points.size(); ++p)
        if (fixed(static_cast<int>(p)) && point_at[p])
          ends.push_back({paper(static_cast<int>(p)), pulleys.count(static_cast<int>(p)) ? pulley_radius + 0.15 : 0});
      for (const auto& [e, stop] : ends)
        if (std::fabs(dot(e - c, n)) < 1e-6 * (1 + len(e) + len(c))) {
          const double s = dot(e, t);
          if (s < lo) lo = std::min(lo, s + stop);
          if (s > hi) hi = std::max(hi, s - stop);
        }
      std::vector<ex> geometry(d.vector.begin(), d.vector.end());
      auto same = std::find_if(surfaces.begin(), surfaces.end(), [&](const Surface& s) {
        return len(s.n - n) < 1e-6 && std::fabs(s.offset - dot(on, n)) < 1e-6 * (1 + std::fabs(s.offset));
      });
      if (same == surfaces.end()) {
        surfaces.push_back({n, dot(on, n), lo, hi, geometry});
      } else {
        same->lo = std::min(same->lo, lo);
        same->hi = std::max(same->hi, hi);
      }
    }
  }

  // Where two surfaces meet (a floor and a wall), neither runs on into the other's ground.
  void trim_surfaces() {
    std::vector<Surface> trimmed = surfaces;
    for (std::size_t i = 0; i < surfaces.size(); ++i)
      for (std::size_t j = 0; j < surfaces.size(); ++j) {
        const Surface &s = surfaces[i], &o = surfaces[j];
        const V t = perp(s.n), to = perp(o.n);
        const double rate = dot(t, o.n);  // how fast s goes into o's ground along t
        if (i == j || std::fabs(rate) < 1e-6) continue;
        const double at = (o.offset - s.offset * dot(s.n, o.n)) / rate;  // s's point on o's line
        const V meet = s.offset * s.n + at * t;
        if (dot(meet, to) < o.lo - 1e-6 || dot(meet, to) > o.hi + 1e-6 || at < s.lo - 1e-6 || at > s.hi + 1e-6)
          continue;
        if (rate > 0)
          trimmed[i].lo = std::max(trimmed[i].lo, at);  // before `at`: o's ground
        else
          trimmed[i].hi = std::min(trimmed[i].hi, at);
      }
    surfaces = trimmed;
  }

  // Each surface hatched; an incline (its ground below it) a triangle on hatched ground (see
  // draw_incline); its angle with the horizontal marked at its foot.
  void draw_surfaces() {
    for (const auto& s : surfaces) {
      const V t = perp(s.n), a = s.offset * s.n + s.lo * t, b = s.offset * s.n + s.hi * t;
      if (std::fabs(t.x) <= 1e-6 || std::fabs(t.y) <= 1e-6) {
        draw_ground(f, a, b, -1 * s.n);
        continue;
      }
      const V foot = a.y < b.y ? a : b, top = a.y < b.y ? b : a;
      const bool triangle = s.n.y > 0 && draw_incline(f, s.n, foot, top, drawn);
      if (!triangle) draw_ground(f, a, b, -1 * s.n);
      marks.push_back({foot, V{top.x > foot.x ? 1.0 : -1.0, 0}, normalized(top - foot),
                       std::acos(std::min(1.0, std::fabs(t.x))), s.geometry, !triangle});
    }
  }

  // Pins: the body held at its point by the ground (draw_support); pins and joints dotted.
  void pins() {
    for (const auto& d : m.drawings) {
      if ((d.as != "pin" && d.as != "joint") || d.point < 0) continue;
      const V p = paper(d.point);
      if (d.as == "pin" && d.body >= 0 && drawn[d.body]) draw_support(f, p, drawn[d.body]->centre);
      dotted.insert(d.point);
      pinned.insert(d.point);
    }
  }

  // Pulleys at their points; a fixed one held by the end of a ground surface near it (the top
  // of an incline), else on a strut to the ground, away from its strands.
  void draw_pulleys() {
    std::map<int, V> leaving = strands_at(m, pulleys, [&](int p) { return paper(p); });
    for (int p : pulleys) {
      FigureOutline o;
      o.shape = FigureOutline::Shape::circle;
      o.centre = fp(paper(p));
      o.radius = pulley_radius;
      o.name = m.points[p].name;
      f.outlines.push_back(o);
      dotted.insert(p);
      if (fixed(p) && !held.count(p)) {
        std::optional<V> nearest;
        for (const auto& sf : surfaces) {
          const V t = perp(sf.n);
          const V q = sf.offset * sf.n + std::clamp(dot(paper(p), t), sf.lo, sf.hi) * t;
          if (len(q - paper(p)) < 1.2 && (!nearest || len(q - paper(p)) < len(*nearest - paper(p)))) nearest = q;
        }
        if (nearest) {
          f.lines.push_back({{fp(paper(p)), fp(*nearest)}, false});
          continue;
        }
        const V away = len(leaving[p]) > 1e-9 ? -1 * normalized(leaving[p]) : V{0, 1};
        const V end = paper(p) + (pulley_radius + 0.45) * away;
        f.lines.push_back({{fp(paper(p)), fp(end)}, false});
        draw_ground(f, end - (support_width / 4) * perp(away), end + (support_width / 4) * perp(away), away);
      }
    }
  }

  // Whether e is in or on a body's outline (a fixed point there is a point of that body,
  // which does not move).
  bool on_a_body(V e) const {
    return std::any_of(drawn.begin(), drawn.end(), [&](const std::optional<Drawn>& b) {
      return b && (inside(b->outline, e) || boundary_distance(b->outline, e) < 0.05);
    });
  }

  // A fixed end of a string, spring, damper or cable that nothing else holds: the ground
  // across it, beyond the end (a ceiling, floor or wall, whichever is nearest across the
  // strand that runs toward `toward`).
  void anchor(int p, V toward) {
    if (!fixed(p) || held.count(p) || pulleys.count(p) || on_a_body(paper(p))) return;
    const V e = paper(p), u = normalized(toward - e);
    const V into = std::fabs(u.y) >= std::fabs(u.x) ? V{0, u.y > 0 ? -1.0 : 1.0} : V{u.x > 0 ? -1.0 : 1.0, 0};
    draw_ground(f, e - (support_width / 2) * perp(into), e + (support_width / 2) * perp(into), into);
    held.insert(p);
  }

  // Strings, springs and dampers along their paths: straight between points, tangent to a
  // pulley where the path turns around it; a spring and a damper between the same points side
  // by side; an end in a body starts at its edge. Cables and rods from their body's edge.
  void strings() {
    std::map<std::pair<int, int>, std::vector<const Model::Drawing*>> between;
    for (const auto& d : m.drawings)
      if ((d.as == "line" || d.as == "spring" || d.as == "damper") && d.path.size() == 2)
        between[{std::min(d.path[0], d.path[1]), std::max(d.path[0], d.path[1])}].push_back(&d);
    for (const auto& d : m.drawings) {
      const bool path = (d.as == "line" || d.as == "spring" || d.as == "damper") && d.path.size() >= 2;
      const bool cable =
          (d.as == "line" && d.path.empty() && d.points.size() >= 2) || (d.as == "rod" && d.points.size() >= 2);
      if (!path && !cable) continue;
      const std::vector<int> pts = path ? d.path : std::vector<int>{d.points[0], d.points[1]};
      const std::vector<double> wrap = wraps(pts);
      std::vector<std::pair<V, V>> pieces = pieces_of(pts, wrap, side_shift(d, pts, between));
      // Ends in a body start at its edge (a rod's or a cable's first end is in its body).
      if (const Drawn* b = cable && d.body >= 0 && drawn[d.body] ? &*drawn[d.body] : body_of(pts.front()))
        pieces.front().first =
            leave(b->outline, pieces.front().first, normalized(pieces.front().second - pieces.front().first));
      if (const Drawn* b = body_of(pts.back()))
        pieces.back().second =
            leave(b->outline, pieces.back().second, normalized(pieces.back().first - pieces.back().second));
      draw_pieces(d, pts, pieces, wrap);
      hold_ends(d, pts, path);
      if (path && pts.size() == 2 && d.as == "line") string_angle(pts);
    }
  }

  // The wrap at each point of a path: its signed radius (positive: the string passes on the
  // left of its way, the pulley on its right, as it turns clockwise).
  std::vector<double> wraps(const std::vector<int>& pts) {
    const std::size_t n = pts.size();
    std::vector<double> wrap(n, 0);
    for (std::size_t k = 1; k + 1 < n; ++k) {
      if (!pulleys.count(pts[k])) continue;
      const V a = paper(pts[k]) - paper(pts[k - 1]), b = paper(pts[k + 1]) - paper(pts[k]);
      const double turn = cross(a, b);
      if (std::fabs(turn) > 1e-9 * len(a) * len(b)) wrap[k] = turn < 0 ? pulley_radius : -pulley_radius;
    }
    return wrap;
  }

  // How far a strand is moved to one side: beside another drawing between the same two points.
  double side_shift(const Model::Drawing& d, const std::vector<int>& pts,
                    std::map<std::pair<int, int>, std::vector<const Model::Drawing*>>& between) {
    double shift = 0;
    if (pts.size() == 2) {
      const auto& group = between[{std::min(pts[0], pts[1]), std::max(pts[0], pts[1])}];
      if (group.size() > 1) {
        const auto at = std::find(group.begin(), group.end(), &d) - group.begin();
        shift = lane * (static_cast<double>(at) - 0.5 * static_cast<double>(group.size() - 1));
      }
    }
    return shift;
  }

  // The tangent points of each strand of a path, from point to point around the wraps; a free
  // end takes the other end's offset, so that the strand stays parallel to its line.
  std::vector<std::pair<V, V>> pieces_of(const std::vector<int>& pts, const std::vector<double>& wrap, double shift) {
    const std::size_t n = pts.size();
    std::vector<std::pair<V, V>> pieces;
    for (std::size_t k = 0; k + 1 < n; ++k) {
      const V q0 = paper(pts[k]), q1 = paper(pts[k + 1]), dq = q1 - q0;
      if (len(dq) < 1e-9) {
        pieces.push_back({q0, q1});
        continue;
      }
      double a = wrap[k], b = wrap[k + 1];
      if (k == 0 && k + 1 < n - 1) a = b;
      if (k + 1 == n - 1 && k > 0) b = a;
      const double ratio = std::clamp((a - b) / len(dq), -1.0, 1.0);
      const double phi = std::atan2(dq.y, dq.x) - std::asin(ratio);
      const V u{std::cos(phi), std::sin(phi)}, nrm = perp(u);
      const V across = shift * perp(normalized(dq));
      pieces.push_back({q0 + a * nrm + across, q1 + b * nrm + across});
    }
    return pieces;
  }

  // Each strand (a rod as a thin bar), then around the pulley to the next strand.
  void draw_pieces(const Model::Drawing& d, const std::vector<int>& pts, const std::vector<std::pair<V, V>>& pieces,
                   const std::vector<double>& wrap) {
    for (std::size_t k = 0; k < pieces.size(); ++k) {
      const auto [p, q] = pieces[k];
      if (len(q - p) < 1e-9) continue;
      if (d.as == "rod") {
        FigureOutline o = rectangle(0.5 * (p + q), q - p, len(q - p), 0.14);
        f.outlines.push_back(o);
      } else {
        draw_strand(f, d.as == "line" ? "line" : d.as, p, q, perp(normalized(q - p)));
      }
      if (k + 1 < pieces.size() && wrap[k + 1] != 0) {
        const V c = paper(pts[k + 1]);
        const double a0 = std::atan2(q.y - c.y, q.x - c.x);
        double a1 = std::atan2(pieces[k + 1].first.y - c.y, pieces[k + 1].first.x - c.x);
        if (wrap[k + 1] > 0) {  // clockwise
          while (a1 > a0) a1 -= 2 * M_PI;
        } else {
          while (a1 < a0) a1 += 2 * M_PI;
        }
        f.lines.push_back({arc(c, pulley_radius, a0, a1), false});
      }
    }
  }

  // What holds the ends: the ground at a path's fixed ends and a cable's, a rod pinned at both
  // ends (at a fixed point, to the ground).
  void hold_ends(const Model::Drawing& d, const std::vector<int>& pts, bool path) {
    const std::size_t n = pts.size();
    if (path) {
      anchor(pts.front(), paper(pts[1]));
      anchor(pts.back(), paper(pts[n - 2]));
    } else if (d.as == "line") {
      anchor(pts.back(), paper(pts.front()));  // a cable from its body to a fixed point
    } else {
      dotted.insert(pts.front());
      dotted.insert(pts.back());
      if (d.as == "rod") pinned.insert({pts.front(), pts.back()});
      if (fixed(pts.back()) && !held.count(pts.back()) && !on_a_body(paper(pts.back()))) {
        draw_support(f, paper(pts.back()), paper(pts.front()));
        held.insert(pts.back());
      }
    }
  }

  // A string from a fixed point to a turning body (a pendulum's): its angle with the vertical
  // there, to mark.
  void string_angle(const std::vector<int>& pts) {
    for (auto [end, other] : {std::pair{pts.front(), pts.back()}, {pts.back(), pts.front()}})
      if (const Drawn* b = body_of(other); b && fixed(end) && !m.bodies[b->body].angle.is_zero()) {
        const Body& body = m.bodies[b->body];
        const V to = normalized(b->centre - paper(end));
        std::vector<ex> geometry{body.angle};
        geometry.insert(geometry.end(), body.cm.begin(), body.cm.end());
        marks.push_back({paper(end), down, to, std::acos(std::clamp(dot(down, to), -1.0, 1.0)), geometry, true});
      }
  }

  // Applied forces: from their point, pulling away from the body (onto its edge where the
  // point is inside it), or pressing on it with the head at the point; labelled with the one
  // component they have, else their magnitude.
  void applied_forces() {
    for (const auto& d : m.drawings) {
      if (d.as != "arrow" || d.body < 0 || !drawn[d.body]) continue;
      const Drawn& b = *drawn[d.body];
      for (const auto& l : m.loads) {
        if (l.source() != d.label || l.body != d.body) continue;
        const auto v = point3(m, num, l.force);
        if (!v || len(proj(*v)) < 1e-12) continue;
        const V u = normalized(proj(*v));
        V at = b.centre;
        if (l.at)
          if (auto p = point3(m, num, *l.at)) at = scale * proj(*p);
        FigureArrow a;
        if (boundary_distance(b.outline, at) < 0.05 && dot(u, b.centre - at) > 1e-9) {
          a.to = fp(at);
          a.from = fp(at - arrow_length * u);
        } else {
          a.from = fp(leave(b.outline, at, u));
          a.to = fp(vp(a.from) + arrow_length * u);
          if (b.hub > 0 && len(vp(a.from) - at) > 1e-9) f.lines.push_back({{fp(at), a.from}, false});  // off the hub
        }
        int nonzero = 0, which = 0;
        for (int k = 0; k < 2; ++k)
          if (std::fabs((*v)[k]) > 1e-12) ++nonzero, which = k;
        ex size = sqrt(pow(l.force[0], 2) + pow(l.force[1], 2));
        if (nonzero == 1) size = (*v)[which] < 0 ? -l.force[which] : l.force[which];
        a.label.tex = to_latex(size);
        f.arrows.push_back(a);
      }
    }
  }

  // Couples: an arc about their body's center, the way they turn; false where one cannot be
  // evaluated.
  bool couples() {
    for (const auto& d : m.drawings) {
      if (d.as != "couple" || d.body < 0 || !drawn[d.body]) continue;
      for (const auto& l : m.loads) {
        if (l.source() != d.label || l.body != d.body || l.couple[2].is_zero()) continue;
        const auto v = num(l.couple[2]);
        if (!v) return false;
        FigureCouple c;
        c.centre = fp(drawn[d.body]->centre);
        const FigureOutline& o = drawn[d.body]->outline;
        c.radius = o.shape == FigureOutline::Shape::circle ? o.radius * 0.6 : 0.5;
        c.counterclockwise = *v >= 0;
        c.label.tex = to_latex(*v >= 0 ? l.couple[2] : -l.couple[2]);
        f.couples.push_back(c);
      }
    }
    return true;
  }

  // The bodies' angles to mark: a rod's with the surface it stands on, a pendulum's with the
  // vertical through its pivot (and with the horizontal).
  void body_angles() {
    for (std::size_t b = 0; b < m.bodies.size(); ++b) {
      if (!drawn[b]) continue;
      const Body& body = m.bodies[b];
      std::vector<ex> geometry{body.angle};
      geometry.insert(geometry.end(), body.cm.begin(), body.cm.end());
      const V centre = drawn[b]->centre;
      if (body.drawn_shape == "rod") {
        const double a = num(body.angle).value_or(0) + proj.turn;
        const V axis{std::cos(a), std::sin(a)};
        for (const auto& [dp, n] : surfaces_of) {
          if (dp->body != static_cast<int>(b)) continue;
          const V c = paper(dp->point);
          const V to = dot(axis, centre - c) >= 0 ? axis : -1 * axis;
          V from = perp(n);
          if (dot(from, centre - c) < 0) from = -1 * from;
          std::vector<ex> g = geometry;
          g.insert(g.end(), dp->vector.begin(), dp->vector.end());
          marks.push_back({c, from, to, std::acos(std::clamp(dot(from, to), -1.0, 1.0)), g, false});
        }
      }
      for (const auto& d : m.drawings) {
        if ((d.as != "pin" && d.as != "joint") || d.point < 0) continue;
        const V p = paper(d.point);
        const bool on_body = std::any_of(m.loads.begin(), m.loads.end(), [&](const Load& l) {
          return l.body == static_cast<int>(b) && l.source() == d.label;
        });
        if (!on_body || len(centre - p) < 0.3) continue;
        const V to = normalized(centre - p);
        marks.push_back({p, down, to, std::acos(std::clamp(dot(down, to), -1.0, 1.0)), geometry, true});
        const V level{to.x >= 0 ? 1.0 : -1.0, 0};
        marks.push_back({p, level, to, std::acos(std::clamp(dot(level, to), -1.0, 1.0)), geometry, true});
      }
    }
  }

  // The angles marked: each where exactly one parameter or coordinate of its geometry has its
  // value (else nothing is marked), a symbol once.
  void choose_marked() {
    std::set<ex, ex_is_less> named_angles;
    for (const auto& mk : marks) {
      if (mk.angle < 1e-3 || mk.angle > M_PI - 1e-3) continue;
      std::set<ex, ex_is_less> symbols, matching;
      for (const ex& g : mk.geometry)
        for (const_preorder_iterator it = g.preorder_begin(); it != g.preorder_end(); ++it)
          if (is_a<symbol>(*it)) symbols.insert(*it);
      for (const ex& s : symbols) {
        const SymbolInfo* info = m.symbols->find(s);
        if (!info || (info->role != SymbolRole::parameter && info->role != SymbolRole::coordinate)) continue;
        if (const auto v = num(s); v && std::fabs(std::fabs(*v) - mk.angle) < 1e-6) matching.insert(s);
      }
      if (matching.size() != 1 || !named_angles.insert(*matching.begin()).second) continue;
      marked.push_back({&mk, *matching.begin()});
    }
  }

  // Each marked angle's arc, dashed, with its reference line where that is not drawn already.
  void draw_marks() {
    for (const auto& [mk, s] : marked) {
      const double r = 0.8;
      if (mk->reference) f.lines.push_back({{fp(mk->vertex), fp(mk->vertex + (r + 0.5) * mk->from)}, true});
      double a0 = std::atan2(mk->from.y, mk->from.x), a1 = std::atan2(mk->to.y, mk->to.x);
      if (a1 - a0 > M_PI) a1 -= 2 * M_PI;
      if (a0 - a1 > M_PI) a1 += 2 * M_PI;
      f.lines.push_back({arc(mk->vertex, r, a0, a1), true});
    }
  }

  // Labels: the forces' at their heads, the couples', the angles', each body's name in it (or
  // beside it), then the points' names.
  void labels() {
    Layout lay(f);
    for (auto& a : f.arrows) {
      const bool pressing = std::any_of(f.outlines.begin(), f.outlines.end(),
                                        [&](const FigureOutline& o) { return boundary_distance(o, vp(a.to)) < 0.06; });
      a.label = place_at_end(lay, a, pressing);
    }
    for (auto& c : f.couples) {
      std::vector<V> cand;
      for (V dir : {V{0, 1}, V{1, 0}, V{-1, 0}, V{0, -1}, V{0.7, 0.7}, V{-0.7, 0.7}})
        cand.push_back(vp(c.centre) + (c.radius + 0.35) * dir);
      c.label = lay.place(c.label.tex, cand);
    }
    for (const auto& [mk, s] : marked) {
      const V mid = normalized(mk->from + mk->to);
      const std::string tex = to_latex(s);
      FigureLabel l =
          lay.place(tex, {mk->vertex + 1.2 * mid, mk->vertex + 1.45 * mid, mk->vertex + 1.2 * mk->to + 0.3 * mid});
      f.texts.push_back(l);
    }
    const std::vector<int> shown = shown_points();
    std::vector<int> named = shown;
    named.insert(named.end(), dotted.begin(), dotted.end());
    body_names(lay, named);
    point_names(lay, shown);
  }

  // The named points: those the connections use that are not a body's own, then the dotted
  // ones, one name where several are in one place.
  std::vector<int> shown_points() {
    std::set<std::string> bodies_named;
    for (const auto& b : m.bodies) bodies_named.insert(b.name);
    std::vector<int> shown;
    for (const auto& d : m.drawings) {
      std::vector<int> used = d.path;
      used.insert(used.end(), d.points.begin(), d.points.end());
      for (int p : used)
        if (!bodies_named.count(m.points[p].name) &&
            std::none_of(shown.begin(), shown.end(), [&](int q) { return len(paper(q) - paper(p)) < 1e-6; }))
          shown.push_back(p);
    }
    for (int p : dotted)
      if (!bodies_named.count(m.points[p].name) && std::find(shown.begin(), shown.end(), p) == shown.end() &&
          std::none_of(shown.begin(), shown.end(), [&](int q) { return len(paper(q) - paper(p)) < 1e-6; }))
        shown.push_back(p);
    return shown;
  }

  // Each body's name in it where it is clear of lines, arrows, the `named` points and pulleys,
  // else beside the body.
  void body_names(Layout& lay, const std::vector<int>& named) {
    for (std::size_t b = 0; b < m.bodies.size(); ++b) {
      if (!drawn[b]) continue;
      const FigureOutline& o = drawn[b]->outline;
      const std::string tex = default_tex(m.bodies[b].name);
      const double w = char_width * static_cast<double>(shown_length(tex)) + 0.12;
      const V c = drawn[b]->centre;
      const Box box{c, w, label_height};
      bool clear = true;
      for (V corner : {c + V{w / 2, label_height / 2}, c + V{-w / 2, label_height / 2}, c + V{w / 2, -label_height / 2},
                       c + V{-w / 2, -label_height / 2}})
        clear = clear && inside(o, corner);
      for (const auto& l : f.lines)
        for (std::size_t i = 1; i < l.points.size(); ++i)
          clear = clear && !box_hits_segment(box, vp(l.points[i - 1]), vp(l.points[i]));
      for (const auto& a : f.arrows) clear = clear && !box_hits_segment(box, vp(a.from), vp(a.to));
      for (int p : named) clear = clear && !overlaps(box, {paper(p), 0.2, 0.2});
      for (const auto& other : f.outlines)
        if (&other != &o && other.shape == FigureOutline::Shape::circle)
          clear = clear && !overlaps(box, {vp(other.centre), 2 * other.radius, 2 * other.radius});
      if (clear) {
        f.texts.push_back(lay.place(tex, {c}));
        continue;
      }
      const auto [x0, x1] = extent_along(o, V{1, 0});
      const auto [y0, y1] = extent_along(o, V{0, 1});
      f.texts.push_back(lay.place(tex, {{x1 + w / 2 + gap, y1 - label_height / 2},
                                        {x0 - w / 2 - gap, y1 - label_height / 2},
                                        {c.x, y1 + label_height / 2 + gap},
                                        {c.x, y0 - label_height / 2 - gap},
                                        {x1 + w / 2 + gap, c.y},
                                        {x0 - w / 2 - gap, c.y}}));
    }
  }

  // The shown points as dots with their names around them; the other dotted points as dots.
  void point_names(Layout& lay, const std::vector<int>& shown) {
    for (int p : shown) {
      FigureDot dot;
      dot.at = fp(paper(p));
      const double r = pulleys.count(p) ? pulley_radius + 0.25 : 0.3;
      std::vector<V> cand;
      for (const double k : {1.0, 1.8})
        for (V dir : {V{-1, 1}, V{1, 1}, V{-1, -1}, V{1, -1}, V{0, 1}, V{-1, 0}, V{1, 0}, V{0, -1}})
          cand.push_back(paper(p) + (k * r) * dir);
      dot.label = lay.place(default_tex(m.points[p].name), cand);
      dot.pin = pinned.count(p) > 0;
      f.dots.push_back(dot);
    }
    for (int p : dotted)
      if (std::find(shown.begin(), shown.end(), p) == shown.end())
        f.dots.push_back({fp(paper(p)), std::nullopt, pinned.count(p) > 0});
  }
};

}  // namespace

std::optional<Figure> FigureMaker::sketch_plane() const {
  PlaneSketch s(m_, [this](const ex& e) { return number(e); });
  std::vector<V> all;
  if (!s.gather(all) || all.empty()) return std::nullopt;
  s.choose_scale(all);
  s.choose_side();
  if (!s.surface_normals()) return std::nullopt;
  s.draw_bodies();
  s.note_pulleys_and_pins();
  s.collect_surfaces();
  s.trim_surfaces();
  s.draw_surfaces();
  s.pins();
  s.draw_pulleys();
  s.strings();
  s.applied_forces();
  if (!s.couples()) return std::nullopt;
  s.body_angles();
  s.choose_marked();
  s.draw_marks();
  s.labels();
  Figure& f = s.f;
  finish(f, {rotate({1, 0}, s.proj.turn), rotate({0, 1}, s.proj.turn)}, m_.axes);
  f.caption = "Sketch of the mechanism";
  f.sketch = true;
  return f;
}

}  // namespace tackle
