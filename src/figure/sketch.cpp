// The sketch of a 1-D mechanism: blocks at their positions along the axis, each string's
// strands side by side in lanes (a strand turns around a sheave where its path reverses),
// springs and dampers, the ground where points are fixed, the applied forces and the axis.
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

constexpr double lane_gap = 1.0;       // between strands side by side (drawing units)
constexpr double sheave_radius = 0.5;  // strands in neighbouring lanes are tangent to it
constexpr double block_length = 1.0;   // a block's size along the axis
constexpr double margin = 0.45;        // a block's edge beyond the strands fixed to it

// A strand of a path: between two points' positions along the axis, in one lane.
struct Strand {
  double s0, s1;   // along the axis, drawing units
  double lat;      // across it
  std::string as;  // line, spring, damper
  int from, to;    // points
};

// Where a path meets a point: its end, a strand passing it, or a sheave it turns around.
struct Meeting {
  int point;
  double s, lat;  // the sheave's centre, for a sheave
  enum class Kind { end, pass, sheave } kind;
  bool pulley = false;  // a pulley connection is at the point (its axle is drawn)
};

// A block as drawn: its extent along and across the axis.
struct Block {
  int body;
  double s_lo, s_hi, lat_lo, lat_hi;
};

// The ground at a fixed point: beyond it along the axis, or a floor below with a post.
struct Ground {
  double s, dir;  // dir 0: a floor below, with a post at s
  double lo = 1e300, hi = -1e300, depth = 0;
};

// A path's strand: a string, spring or damper with at least two points.
bool is_path(const Model::Drawing& d) {
  return d.path.size() >= 2 && (d.as == "line" || d.as == "spring" || d.as == "damper");
}

// Whether a body is drawn as a block: unless its mass is 0 (a pulley block, drawn as its sheaves).
bool massive(const Body& b) { return !(b.has_mass && b.mass.is_zero()); }

// How far a path reaches from a point along the axis: a sheave's radius, else nothing.
double reach(const Meeting& t) { return t.kind == Meeting::Kind::sheave ? sheave_radius : 0.0; }

// The steps of a 1-D sketch and what they share: the positions along the axis, the strands
// in their lanes, where paths meet points, the blocks, and the figure they draw into.
struct LineSketch {
  const Model& m;
  Number num;
  V axis{1, 0};  // on paper
  V across;
  std::vector<std::optional<double>> pos;       // a point's position along the axis, model units
  std::vector<std::optional<double>> body_pos;  // a body's
  std::vector<double> used;                     // the positions the sketch spans
  std::set<int> supported;                      // bodies a support holds
  std::map<int, bool> pulley_at;                // points with a pulley
  double scale = 1;                             // model units to drawing units
  std::vector<Strand> strands;
  std::vector<Meeting> meetings;
  Figure f;
  std::vector<Block> blocks;
  std::vector<std::pair<V, V>> hangers;  // from a block to a point of its body away from it

  // The axis on paper: vertical when gravity acts along it (up the page against it). An
  // axis named y or z is drawn vertical, as a person would.
  LineSketch(const Model& model, Number number)
      : m(model), num(std::move(number)), pos(model.points.size()), body_pos(model.bodies.size()) {
    if (m.axes[0] == "y" || m.axes[0] == "z") axis = {0, 1};
    if (m.gravity)
      if (auto g = num((*m.gravity)[0]); g && *g != 0) axis = {0, *g < 0 ? 1.0 : -1.0};
    across = axis.x != 0 ? V{0, 1} : V{1, 0};
  }

  // The place on paper s along the axis and lat across it.
  V at(double s, double lat) const { return s * axis + lat * across; }

  // A point's position along the axis, drawing units.
  double s_of(int p) const { return scale * *pos[p]; }

  // Positions along the axis, in model units: the points the drawings use and every body;
  // the supported bodies and the pulleys' points. False where one cannot be evaluated.
  bool positions() {
    auto need_point = [&](int p) {
      if (!pos[p]) pos[p] = num(m.points[p].position[0]);
      if (pos[p]) used.push_back(*pos[p]);
      return pos[p].has_value();
    };
    for (const auto& d : m.drawings) {
      for (int p : d.path)
        if (!need_point(p)) return false;
      if (d.as == "pulley" && d.point >= 0) pulley_at[d.point] = true;
      if (d.as == "support" && d.body >= 0) supported.insert(d.body);
    }
    for (std::size_t b = 0; b < m.bodies.size(); ++b) {
      body_pos[b] = num(m.bodies[b].cm[0]);
      if (!body_pos[b]) return false;
      if (massive(m.bodies[b])) used.push_back(*body_pos[b]);
    }
    return true;
  }

  // The scale: about 8 units long in all, things apart by at least 2.2 units where that fits
  // in 12.
  void choose_scale() {
    std::sort(used.begin(), used.end());
    double extent = used.back() - used.front(), closest = 1e300;
    for (std::size_t i = 1; i < used.size(); ++i)
      if (used[i] - used[i - 1] > 1e-9 * (1 + extent)) closest = std::min(closest, used[i] - used[i - 1]);
    scale = extent > 1e-12 ? std::min(2.5, 8 / extent) : 1;
    if (closest < 1e300 && closest * scale < 2.2)
      scale = std::min(2.2 / closest, extent > 1e-12 ? 12 / extent : 2.2 / closest);
  }

  // Strands in lanes: each path takes the lowest free lanes (0, 1, -1, 2, ...); it moves to
  // the next lane where it turns back around a point.
  void lay_strands() {
    std::map<int, std::vector<std::pair<double, double>>> busy;
    for (const auto& d : m.drawings)
      if (is_path(d)) lay_path(d, busy);
  }

  // Each strand's lane relative to the path's first: one more after each turn back.
  std::vector<int> relative_lanes(const Model::Drawing& d) const {
    const std::size_t n = d.path.size();
    std::vector<int> rel(n - 1, 0);
    int lane = 0;
    double last = 0;  // the direction of the last strand that has a length
    for (std::size_t k = 0; k + 1 < n; ++k) {
      const double dir = s_of(d.path[k + 1]) - s_of(d.path[k]);
      if (std::fabs(dir) > 1e-9) {
        if (last * dir < 0) ++lane;
        last = dir;
      }
      rel[k] = lane;
    }
    return rel;
  }

  // The lowest lane (0, 1, -1, 2, ...) from which the path's strands are clear of those laid.
  int free_lane(const Model::Drawing& d, const std::vector<int>& rel,
                std::map<int, std::vector<std::pair<double, double>>>& busy) const {
    const std::size_t n = d.path.size();
    auto fits = [&](int base) {
      for (std::size_t k = 0; k + 1 < n; ++k) {
        const double a = std::min(s_of(d.path[k]), s_of(d.path[k + 1])),
                     b = std::max(s_of(d.path[k]), s_of(d.path[k + 1]));
        if (b - a < 1e-9) continue;
        for (const auto& [lo, hi] : busy[base + rel[k]])
          if (std::min(hi, b) - std::max(lo, a) > 1e-6) return false;
      }
      return true;
    };
    int base = 0;
    for (int tries = 0; tries < 64; ++tries) {
      base = ((tries + 1) / 2) * (tries % 2 ? 1 : -1);
      if (fits(base)) break;
    }
    return base;
  }

  // One path's strands in their lanes, and where it meets its points: its ends, the points
  // it passes, the sheaves it turns around.
  void lay_path(const Model::Drawing& d, std::map<int, std::vector<std::pair<double, double>>>& busy) {
    const std::size_t n = d.path.size();
    const std::vector<int> rel = relative_lanes(d);
    const int base = free_lane(d, rel, busy);
    for (std::size_t k = 0; k + 1 < n; ++k) {
      const double a = s_of(d.path[k]), b = s_of(d.path[k + 1]);
      if (std::fabs(b - a) < 1e-9) continue;
      busy[base + rel[k]].push_back({std::min(a, b), std::max(a, b)});
      strands.push_back({a, b, lane_gap * (base + rel[k]), d.as, d.path[k], d.path[k + 1]});
    }
    auto meet = [&](int p, double lat, Meeting::Kind kind) {
      meetings.push_back({p, s_of(p), lat, kind, pulley_at.count(p) > 0});
    };
    meet(d.path.front(), lane_gap * (base + rel.front()), Meeting::Kind::end);
    for (std::size_t k = 1; k + 1 < n; ++k) {
      if (rel[k] != rel[k - 1])
        meet(d.path[k], lane_gap * (base + 0.5 * (rel[k - 1] + rel[k])), Meeting::Kind::sheave);
      else
        meet(d.path[k], lane_gap * (base + rel[k]), Meeting::Kind::pass);
    }
    meet(d.path.back(), lane_gap * (base + rel.back()), Meeting::Kind::end);
  }

  // Blocks: the bodies with mass, at their positions, across the lanes fixed to them, wide
  // enough for their names.
  void size_blocks() {
    for (std::size_t b = 0; b < m.bodies.size(); ++b) {
      const Body& body = m.bodies[b];
      if (!massive(body)) continue;
      const double c = scale * *body_pos[b];
      Block k{static_cast<int>(b), c - block_length / 2, c + block_length / 2, 1e300, -1e300};
      for (const auto& t : meetings) {
        if (m.points[t.point].body != static_cast<int>(b)) continue;
        const double extra = t.kind == Meeting::Kind::sheave ? sheave_radius + 0.25 : margin;
        k.lat_lo = std::min(k.lat_lo, t.lat - extra);
        k.lat_hi = std::max(k.lat_hi, t.lat + extra);
        if (std::fabs(t.s - c) <= block_length / 2 + 1e-9) {
          k.s_lo = std::min(k.s_lo, t.s - reach(t) - 0.25 * (t.kind == Meeting::Kind::sheave));
          k.s_hi = std::max(k.s_hi, t.s + reach(t) + 0.25 * (t.kind == Meeting::Kind::sheave));
        }
      }
      if (k.lat_lo > k.lat_hi) k.lat_lo = -margin, k.lat_hi = margin;
      const double name = char_width * static_cast<double>(shown_length(default_tex(body.name))) + 0.3;
      if (axis.x != 0 && k.s_hi - k.s_lo < name) k.s_lo = c - name / 2, k.s_hi = c + name / 2;
      if (axis.x == 0 && k.lat_hi - k.lat_lo < name) {
        const double mid = (k.lat_lo + k.lat_hi) / 2;
        k.lat_lo = mid - name / 2;
        k.lat_hi = mid + name / 2;
      }
      blocks.push_back(k);
    }
  }

  // Bodies in contact touch: the facing sides of two blocks meet halfway between them, each
  // keeping a quarter of a block's length at least.
  void touch_blocks() {
    for (const auto& d : m.drawings) {
      if (d.as != "contact" || d.path.size() != 2) continue;
      auto block = [&](int point) {
        return std::find_if(blocks.begin(), blocks.end(),
                            [&](const Block& k) { return k.body == m.points[point].body; });
      };
      auto a = block(d.path[0]), b = block(d.path[1]);
      if (a == blocks.end() || b == blocks.end() || a == b) continue;
      if (a->s_lo + a->s_hi > b->s_lo + b->s_hi) std::swap(a, b);  // a below b along the axis
      const double lo = a->s_lo + 0.25 * block_length, hi = b->s_hi - 0.25 * block_length;
      const double mid = lo <= hi ? std::clamp(0.5 * (a->s_hi + b->s_lo), lo, hi) : 0.5 * (lo + hi);
      a->s_hi = b->s_lo = mid;
    }
  }

  // Each block's outline; a point of the body away from the block hangs from it.
  void draw_blocks() {
    for (const auto& k : blocks) {
      for (const auto& t : meetings) {
        if (m.points[t.point].body != k.body || (t.s >= k.s_lo - 1e-9 && t.s <= k.s_hi + 1e-9)) continue;
        const double edge = t.s > k.s_hi ? k.s_hi : k.s_lo, dir = t.s > k.s_hi ? 1 : -1;
        hangers.push_back({at(edge, t.lat), at(t.s - dir * reach(t), t.lat)});
      }
      FigureOutline o;
      for (auto [s, l] : {std::pair{k.s_lo, k.lat_lo}, {k.s_hi, k.lat_lo}, {k.s_hi, k.lat_hi}, {k.s_lo, k.lat_hi}})
        o.corners.push_back(fp(at(s, l)));
      o.name = m.bodies[k.body].name;
      f.outlines.push_back(o);
    }
  }

  // The block of a point's body, if it has one.
  const Block* block_of(int point) const {
    for (const auto& k : blocks)
      if (k.body == m.points[point].body) return &k;
    return nullptr;
  }

  // Sheaves, over the blocks they are fixed to (a pulley's axle dotted).
  void sheaves() {
    for (const auto& t : meetings)
      if (t.kind == Meeting::Kind::sheave) {
        FigureOutline o;
        o.shape = FigureOutline::Shape::circle;
        o.centre = fp(at(t.s, t.lat));
        o.radius = sheave_radius;
        o.name = m.points[t.point].name;
        f.outlines.push_back(o);
        if (t.pulley) f.dots.push_back({o.centre, std::nullopt});
      }
  }

  // Where a strand's end at s ends: in a block, tied to the block's edge (facing `toward`),
  // unless it leaves a sheave there.
  double tied(int point, double s, double lat, double toward) const {
    const Block* k = block_of(point);
    if (!k || s < k->s_lo - 1e-9 || s > k->s_hi + 1e-9) return s;
    for (const auto& t : meetings)
      if (t.point == point && t.kind == Meeting::Kind::sheave && std::fabs(t.s - s) < 1e-9 &&
          std::fabs(std::fabs(t.lat - lat) - sheave_radius) < 1e-9)
        return s;
    return toward > 0 ? k->s_hi : k->s_lo;
  }

  // The strands between their tied ends, then the hangers.
  void draw_strands() {
    for (const auto& st : strands) {
      const double dir = st.s1 > st.s0 ? 1 : -1;
      const double a = tied(st.from, st.s0, st.lat, dir), b = tied(st.to, st.s1, st.lat, -dir);
      if ((b - a) * dir <= 1e-9) continue;
      const V p = at(a, st.lat), q = at(b, st.lat);
      draw_strand(f, st.as, p, q, across);
    }
    for (const auto& [p, q] : hangers) f.lines.push_back({{fp(p), fp(q)}, false});
  }

  // The ground: where a point is fixed (or its body held), beyond it, away from the moving
  // bodies; below everything, with a post, when moving bodies are on both sides of it.
  void ground() {
    double lowest = 0;
    for (const auto& st : strands) lowest = std::min(lowest, st.lat);
    for (const auto& k : blocks) lowest = std::min(lowest, k.lat_lo);
    for (const auto& t : meetings) lowest = std::min(lowest, t.lat - reach(t));
    std::vector<double> moving;
    for (const auto& k : blocks) moving.push_back(0.5 * (k.s_lo + k.s_hi));
    for (const auto& t : meetings) {
      const int b = m.points[t.point].body;
      if (b >= 0 && !supported.count(b)) moving.push_back(t.s);
    }
    std::vector<Ground> grounds;
    std::vector<std::pair<Meeting, std::size_t>> fixed;  // meeting, its ground
    std::set<std::pair<int, long long>> seen;
    for (const auto& t : meetings) {
      const int b = m.points[t.point].body;
      if ((b >= 0 && !supported.count(b)) || t.kind == Meeting::Kind::pass) continue;
      if (!seen.insert({t.point, std::llround(t.lat * 1000)}).second) continue;
      const bool below = std::any_of(moving.begin(), moving.end(), [&](double s) { return s < t.s - 1e-6; });
      const bool above = std::any_of(moving.begin(), moving.end(), [&](double s) { return s > t.s + 1e-6; });
      const double dir = !above ? 1 : !below ? -1 : 0;
      auto it = std::find_if(grounds.begin(), grounds.end(),
                             [&](const Ground& g) { return g.dir == dir && std::fabs(g.s - t.s) < 1e-6; });
      if (it == grounds.end()) it = grounds.insert(grounds.end(), Ground{t.s, dir});
      it->lo = std::min(it->lo, t.lat);
      it->hi = std::max(it->hi, t.lat);
      it->depth = std::max(it->depth, reach(t) > 0 ? reach(t) + 0.35 : 0.0);
      fixed.push_back({t, static_cast<std::size_t>(it - grounds.begin())});
    }
    for (const auto& [t, gi] : fixed) {
      const Ground& g = grounds[gi];
      if (g.dir != 0) {
        const double sg = g.s + g.dir * g.depth;
        if (std::fabs(sg - (t.s + g.dir * reach(t))) > 1e-9)
          f.lines.push_back({{fp(at(t.s + g.dir * reach(t), t.lat)), fp(at(sg, t.lat))}, false});
      }
    }
    for (const auto& g : grounds) draw_ground_at(g, lowest);
  }

  // One ground: hatched beyond its points, or a floor below `lowest` with its post, broken
  // where a strand passes it.
  void draw_ground_at(const Ground& g, double lowest) {
    if (g.dir != 0) {
      const double sg = g.s + g.dir * g.depth, lo = g.lo - 0.6, hi = g.hi + 0.6;
      draw_ground(f, at(sg, lo), at(sg, hi), g.dir * axis);
      return;
    }
    const double floor = lowest - 0.9;
    std::vector<double> passing;
    for (const auto& t : meetings)
      if (t.kind == Meeting::Kind::pass && std::fabs(t.s - g.s) < 1e-6 && t.lat > floor && t.lat < g.hi)
        passing.push_back(t.lat);
    std::sort(passing.begin(), passing.end());
    double from = floor;
    for (double l : passing) {
      if (l - 0.12 > from) f.lines.push_back({{fp(at(g.s, from)), fp(at(g.s, l - 0.12))}, false});
      from = l + 0.12;
    }
    f.lines.push_back({{fp(at(g.s, from)), fp(at(g.s, g.hi))}, false});
    draw_ground(f, at(g.s - 0.6, floor), at(g.s + 0.6, floor), -1 * across);
  }

  // A string's end tied to a fixed point or a massless body: a dot.
  void end_dots() {
    for (const auto& t : meetings)
      if (t.kind == Meeting::Kind::end && !block_of(t.point)) f.dots.push_back({fp(at(t.s, t.lat)), std::nullopt});
  }

  // Applied forces, from the edge of their block (or the sheave of a massless body).
  void applied_forces() {
    for (const auto& d : m.drawings) {
      if (d.as != "arrow" || d.body < 0) continue;
      for (const auto& l : m.loads) {
        if (l.source() != d.label || l.body != d.body) continue;
        const auto v = num(l.force[0]);
        if (!v || std::fabs(*v) < 1e-12) continue;
        const double dir = *v > 0 ? 1 : -1;
        const ex shown = *v > 0 ? l.force[0] : -l.force[0];
        double s = scale * *body_pos[d.body], lat = 0;
        if (auto k = std::find_if(blocks.begin(), blocks.end(), [&](const Block& b) { return b.body == d.body; });
            k != blocks.end()) {
          s = dir > 0 ? k->s_hi : k->s_lo;
          lat = 0.5 * (k->lat_lo + k->lat_hi);
        } else {
          for (const auto& t : meetings)
            if (m.points[t.point].body == d.body) {
              s = t.s + dir * reach(t);
              lat = t.lat;
              break;
            }
        }
        FigureArrow a;
        a.from = fp(at(s, lat));
        a.to = fp(at(s, lat) + (arrow_length * dir) * axis);
        a.label.tex = to_latex(shown);
        f.arrows.push_back(a);
      }
    }
  }

  // Labels: the forces' at their heads, the blocks' names, then the points' names (fixed
  // points, sheaves, the points of a body away from its own name).
  void labels() {
    Layout lay(f);
    for (auto& a : f.arrows) a.label = place_at_end(lay, a, false);
    block_names(lay);
    point_names(lay);
  }

  // Each block's name inside it, or beside it when a sheave or a strand is in the way.
  void block_names(Layout& lay) {
    for (const auto& k : blocks) {
      const std::string tex = default_tex(m.bodies[k.body].name);
      const V c = at(0.5 * (k.s_lo + k.s_hi), 0.5 * (k.lat_lo + k.lat_hi));
      const double w = char_width * static_cast<double>(shown_length(tex)) + 0.12;
      bool clear = true;
      const Box box{c, w, label_height};
      for (const auto& o : f.outlines)
        if (o.shape == FigureOutline::Shape::circle && overlaps(box, {vp(o.centre), 2 * o.radius, 2 * o.radius}))
          clear = false;
      for (const auto& l : f.lines)
        for (std::size_t i = 1; i < l.points.size(); ++i)
          if (box_hits_segment(box, vp(l.points[i - 1]), vp(l.points[i]))) clear = false;
      if (clear) {
        f.texts.push_back(lay.place(tex, {c}));
        continue;
      }
      const V lo = at(k.s_lo, k.lat_lo), hi = at(k.s_hi, k.lat_hi);
      const double x0 = std::min(lo.x, hi.x), x1 = std::max(lo.x, hi.x), y0 = std::min(lo.y, hi.y),
                   y1 = std::max(lo.y, hi.y);
      f.texts.push_back(lay.place(tex, {{x0 - w / 2 - gap, y1 - label_height / 2},
                                        {x1 + w / 2 + gap, y1 - label_height / 2},
                                        {x0 + w / 2, y1 + label_height / 2 + gap},
                                        {x0 + w / 2, y0 - label_height / 2 - gap},
                                        {x0 - w / 2 - gap, y0 + label_height / 2},
                                        {x1 + w / 2 + gap, y0 + label_height / 2}}));
    }
  }

  // The names of the points where paths end or turn, once each, but not of a point in its
  // block (the block's name says it).
  void point_names(Layout& lay) {
    std::set<int> named;
    for (const auto& t : meetings) {
      const Point& p = m.points[t.point];
      if (const Block* k = block_of(t.point); k && t.s >= k->s_lo - 1e-9 && t.s <= k->s_hi + 1e-9) continue;
      if (t.kind == Meeting::Kind::pass || !named.insert(t.point).second) continue;
      const V c = at(t.s, t.lat);
      const std::string tex = default_tex(p.name);
      const double r = reach(t) + 0.15, w = char_width * static_cast<double>(shown_length(tex)) + 0.12;
      std::vector<V> cand;
      for (V d : {V{-1, 1}, V{1, 1}, V{-1, -1}, V{1, -1}, V{0, 1}, V{-1, 0}, V{1, 0}, V{0, -1}})
        cand.push_back(c + V{d.x * (r * std::fabs(normalized(d).x) + w / 2),
                             d.y * (r * std::fabs(normalized(d).y) + label_height / 2)});
      f.texts.push_back(lay.place(tex, cand));
    }
  }

  // Gravity along the axis, as the book marks it: an arrow beside the mechanism (after its
  // bounds are known), labelled with its size along the axis (g, or g sin(theta) on an incline).
  void gravity_arrow() {
    if (!m.gravity) return;
    if (auto g = num((*m.gravity)[0]); g && std::fabs(*g) > 1e-12) {
      FigureArrow a;
      const V dir = (*g > 0 ? 1.0 : -1.0) * axis;
      const V side = axis.x != 0 ? V{0, f.max_y + 0.5} : V{f.max_x + 0.6, 0};
      const V mid = axis.x != 0 ? V{0.5 * (f.min_x + f.max_x), side.y} : V{side.x, 0.5 * (f.min_y + f.max_y)};
      a.from = fp(mid - 0.5 * dir);
      a.to = fp(mid + 0.5 * dir);
      a.label.tex = to_latex(*g > 0 ? (*m.gravity)[0] : -(*m.gravity)[0]);
      a.label.width = char_width * static_cast<double>(shown_length(a.label.tex)) + 0.12;
      a.label.height = label_height;
      a.label.at = fp(mid + V{a.label.width / 2 + 0.15, 0});  // to its right
      f.arrows.push_back(a);
      f.max_x = std::max(f.max_x, a.label.at.x + a.label.width / 2);
      f.max_y = std::max({f.max_y, a.from.y, a.to.y, a.label.at.y + a.label.height / 2});
      f.min_y = std::min({f.min_y, a.from.y, a.to.y});
    }
  }
};

}  // namespace

std::optional<Figure> mechanism_sketch(const Model& m) { return FigureMaker(m).sketch(); }

std::optional<Figure> FigureMaker::sketch() const {
  if (m_.dims() == 1) return sketch_line();
  if (m_.dims() == 2) return sketch_plane();
  return std::nullopt;
}

std::optional<Figure> FigureMaker::sketch_line() const {
  if (std::none_of(m_.drawings.begin(), m_.drawings.end(), is_path)) return std::nullopt;
  PersonOrder order(factor_rank({m_.symbols}));
  LineSketch s(m_, [this](const ex& e) { return number(e); });
  if (!s.positions()) return std::nullopt;
  s.choose_scale();
  s.lay_strands();
  s.size_blocks();
  s.touch_blocks();
  s.draw_blocks();
  s.sheaves();
  s.draw_strands();
  s.ground();
  s.end_dots();
  s.applied_forces();
  s.labels();
  finish(s.f, {s.axis}, {m_.axes[0]});
  s.gravity_arrow();
  s.f.caption = "Sketch of the mechanism";
  s.f.sketch = true;
  return s.f;
}

}  // namespace tackle
