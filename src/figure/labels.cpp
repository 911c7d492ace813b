#include "figure/labels.hpp"

namespace tackle::fig {

namespace {

// The SVG writer's arrowhead: a marker 7 stroke widths long and wide (2 px for a force, 1 px
// for an axis, at 40 px a unit), its tip at the line's end.
constexpr double px = 1.0 / 40;
constexpr double dot_half = 0.0625;  // a point's dot (2.5 px in SVG, 1.5 pt in TikZ), as a square

// An arc as drawn: the chords between the points of fig::arc.
void add_chords(std::vector<Stroke>& out, V centre, double r, double from, double to) {
  const std::vector<FigurePoint> points = arc(centre, r, from, to);
  for (std::size_t k = 1; k < points.size(); ++k) out.push_back({vp(points[k - 1]), vp(points[k])});
}

void add_head(std::vector<Stroke>& out, V tip, V direction, double stroke_width) {
  if (len(direction) < 1e-12) return;
  const V d = normalized(direction);
  const double length = 7 * stroke_width * px;
  const V back = tip - length * d, side = (length / 2) * perp(d);
  out.push_back({tip, back + side});
  out.push_back({back + side, back - side});
  out.push_back({back - side, tip});
}

void add_outline(std::vector<Stroke>& out, const FigureOutline& o) {
  if (o.shape == FigureOutline::Shape::circle) {
    add_chords(out, vp(o.centre), o.radius, 0, 2 * M_PI);
    return;
  }
  for (std::size_t i = 0; i < o.corners.size(); ++i)
    out.push_back({vp(o.corners[i]), vp(o.corners[(i + 1) % o.corners.size()])});
}

void add_couple(std::vector<Stroke>& out, const FigureCouple& c) {
  const double start = (c.counterclockwise ? -60.0 : 240.0) * M_PI / 180,
               end = (c.counterclockwise ? 240.0 : -60.0) * M_PI / 180;
  add_chords(out, vp(c.centre), c.radius, start, end);
  const V tip = vp(c.centre) + c.radius * V{std::cos(end), std::sin(end)};
  const V tangent = c.counterclockwise ? V{-std::sin(end), std::cos(end)} : V{std::sin(end), -std::cos(end)};
  add_head(out, tip, tangent, 2);
}

// The label's box at `at`.
Box box_at(const FigureLabel& l, V at) { return {at, l.width, l.height}; }

}  // namespace

std::vector<Stroke> strokes(const Figure& f) {
  std::vector<Stroke> out;
  for (const auto& o : f.outlines) add_outline(out, o);
  for (const auto& l : f.lines)
    for (std::size_t i = 1; i < l.points.size(); ++i) out.push_back({vp(l.points[i - 1]), vp(l.points[i])});
  for (const auto& d : f.dots) {
    const V c = vp(d.at);
    const V a = c + V{-dot_half, -dot_half}, b = c + V{dot_half, -dot_half}, e = c + V{dot_half, dot_half},
            g = c + V{-dot_half, dot_half};
    out.insert(out.end(), {{a, b}, {b, e}, {e, g}, {g, a}});
  }
  for (const auto& a : f.arrows) {
    out.push_back({vp(a.from), vp(a.to)});
    add_head(out, vp(a.to), vp(a.to) - vp(a.from), a.axis ? 1 : 2);
  }
  for (const auto& c : f.couples) add_couple(out, c);
  return out;
}

std::vector<FigureLabel*> labels_of(Figure& f) {
  std::vector<FigureLabel*> out;
  for (auto& t : f.texts) out.push_back(&t);
  for (auto& d : f.dots)
    if (d.label) out.push_back(&*d.label);
  for (auto& a : f.arrows) out.push_back(&a.label);
  for (auto& c : f.couples) out.push_back(&c.label);
  return out;
}

int crossings(const Box& box, const std::vector<Stroke>& drawn, const std::vector<FigureLabel*>& labels,
              std::size_t before) {
  int n = 0;
  for (const auto& s : drawn)
    if (box_hits_segment(box, s.p, s.q)) ++n;
  const Box roomy{box.c, box.w + label_spacing, box.h + label_spacing};
  for (std::size_t i = 0; i < std::min(before, labels.size()); ++i)
    if (labels[i]->width > 0 && overlaps(roomy, box_at(*labels[i], vp(labels[i]->at)))) ++n;
  return n;
}

void settle_labels(Figure& f) {
  const std::vector<Stroke> drawn = strokes(f);
  const std::vector<FigureLabel*> labels = labels_of(f);
  for (std::size_t i = 0; i < labels.size(); ++i) {
    FigureLabel& l = *labels[i];
    if (l.width <= 0 || l.tex.empty()) continue;
    const V home = vp(l.at);
    int least = crossings(box_at(l, home), drawn, labels, i);
    V best = home;
    // Rings around the label's box, nearest first; the first ring with a free place gives
    // the place nearest to where the label was.
    for (int ring = 1; ring <= 16 && least > 0; ++ring) {
      const double r = 0.1 * ring;
      double nearest = 1e300;
      for (int k = 0; k < 32; ++k) {
        const double a = 2 * M_PI * k / 32;
        const V at = home + r * V{std::cos(a), std::sin(a)};
        const int n = crossings(box_at(l, at), drawn, labels, i);
        const double distance = len(at - home);
        if (n < least || (n == least && n == 0 && distance < nearest)) {
          least = n;
          best = at;
          nearest = distance;
        }
      }
    }
    l.at = fp(best);
  }
}

}  // namespace tackle::fig
