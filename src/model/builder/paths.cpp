// The paths of connections (strings, springs, dampers): made once per points argument, with
// a positive length symbol for each strand that turns as the bodies move.
#include "model/builder/stages.hpp"

#include <algorithm>

#include "expr/print.hpp"
#include "expr/trig.hpp"
#include "model/kinematics.hpp"

namespace tackle::build {

using namespace GiNaC;

namespace {

// The symbol for the length of a strand that turns (one per pair of points, whichever way
// round): l_CP, or l_C_P1 when a name is longer than one letter, with l^2 = `squared`.
ex turning_length(BuildContext& ctx, const Point& a, const Point& b, const ex& squared) {
  const auto key = std::minmax(a.name, b.name);
  if (auto it = ctx.turning_lengths.find(key); it != ctx.turning_lengths.end()) return it->second;
  // Two strands of one length at every position (mirror images about a body's line) are one
  // symbol: with two, their difference would not cancel (a balance across the line would
  // read a T (1/l_QP - 1/l_A1Q) = 0 and be called inconsistent).
  for (const auto& l : ctx.m.lengths)
    if ((l.squared - squared).expand().is_zero()) {
      ctx.turning_lengths.emplace(key, l.symbol);
      for (const Point* p : {&a, &b}) ctx.turning_at.emplace(ctx.point_index.at(p->name), a.name + "-" + b.name);
      return l.symbol;
    }
  const bool short_names = a.name.size() == 1 && b.name.size() == 1;
  const std::string base = "l_" + a.name + (short_names ? "" : "_") + b.name;
  std::string name = base;
  for (int k = 2; ctx.table->find(name); ++k) name = base + "_" + std::to_string(k);
  const std::string tex = "\\ell" + default_tex(name).substr(1);
  const SymbolInfo& s = ctx.table->add(name, tex, SymbolRole::parameter, Dimension::length(), true, Location{});
  ctx.table->set_definition(name, sqrt(squared), true);
  ctx.table->set_unit(name, "m", 1);
  ctx.m.lengths.push_back({s.sym, squared});
  ctx.turning_lengths.emplace(key, s.sym);
  for (const Point* p : {&a, &b}) ctx.turning_at.emplace(ctx.point_index.at(p->name), a.name + "-" + b.name);
  return s.sym;
}

// A path that ends at a point of a turning body that keeps the ground's directions (`turns:
// false`) winds on that body there: a drum, a pulley the string grips, a spool. The strand
// leaves the rim along a tangent, and as the body turns by d(angle) the string winds on or
// off by r d(angle): the path's length gains s angle, with s = d . (z x r) (d the strand's
// direction into the rim point, r the point's offset from the center), which is +-|r| for a
// tangent. Its tension then acts on the body at that point (a moment about its center).
bool wind(BuildContext& ctx, const Instance& in, Path& path) {
  bool ok = true;
  for (const bool last : {false, true}) {
    const int index = last ? path.points.back() : path.points.front();
    const Point& p = ctx.m.points[index];
    if (p.body < 0 || p.turns) continue;
    const Body& body = ctx.m.bodies[p.body];
    if (body.angle.is_zero()) continue;
    PathSegment& seg = last ? path.segments.back() : path.segments.front();
    const Point& other = ctx.m.points[last ? seg.from : seg.to];
    const Vec into = last ? seg.direction : -1 * seg.direction;
    const ex s = fewer_trig_terms(normal(inner(into, cross(Vec{0, 0, 1}, p.offset))));
    const std::string strand = "the strand " + other.name + "-" + p.name + " of " + in.label;
    bool moves = false;
    for (const auto& c : ctx.m.coordinates) moves = moves || s.has(c.q);
    for (const auto& l : ctx.m.lengths) moves = moves || s.has(l.symbol);
    if (moves) {
      ctx.diags.error(in.c.at,
                      strand + " leaves body '" + body.name + "' at '" + p.name +
                          "' in a direction that changes as the bodies move (expected a strand that stays along one "
                          "line, as from a drum to a hanging or sliding body)");
      ok = false;
      continue;
    }
    if (!normal(s * s - inner(p.offset, p.offset)).is_zero()) {
      ctx.diags.error(in.c.at, strand + " does not leave body '" + body.name + "' along a tangent at '" + p.name +
                                   "' (a string winds on a turning body where it leaves the rim at right angles to the "
                                   "radius; expected the strand at right angles to the offset " +
                                   to_text(p.offset[0]) + ", " + to_text(p.offset[1]) + ")");
      ok = false;
      continue;
    }
    path.length += s * body.angle;
    path.varying_length += s * body.angle;
    seg.constant = false;  // its tension turns the body even when the strand's length is fixed
  }
  return ok;
}

}  // namespace

// The path of a points argument, made on first use; nothing when it cannot be made (its
// problems are reported then).
const Path* path_of(BuildContext& ctx, Instance& in, const std::string& key) {
  auto it = in.path_args.find(key);
  if (it == in.path_args.end()) return nullptr;
  // A body whose coordinate could not be made has been reported already.
  for (int p : it->second)
    if (ctx.m.dims() == 1 && ctx.m.points[p].body >= 0 &&
        !kinematics::translation(ctx.m, ctx.m.bodies[ctx.m.points[p].body]))
      return nullptr;
  auto [cached, fresh] = in.paths.try_emplace(key);
  if (fresh) {
    cached->second = make_path(
        it->second, ctx.m.points, ctx.m.dims(), ctx.layout, ctx.diags, in.c.at, in.label,
        [&ctx](const Point& a, const Point& b, const ex& squared) { return turning_length(ctx, a, b, squared); });
    if (cached->second && ctx.m.dims() == 2 && !wind(ctx, in, *cached->second)) cached->second.reset();
    if (cached->second && cached->second->varying_length.is_zero()) {
      ctx.diags.error(in.c.at, "the path of a " + in.what +
                                   " never changes length (its ends are on one body, or fixed; expected a path between "
                                   "points that move apart)");
      cached->second.reset();
    }
    // The strands whose length changes and stays a polynomial (a turning strand's root never
    // reaches zero short of the two points meeting), each once.
    if (cached->second)
      for (const auto& seg : cached->second->segments) {
        if (seg.constant) continue;
        const bool turning = std::any_of(ctx.m.lengths.begin(), ctx.m.lengths.end(),
                                         [&](const TurningLength& l) { return seg.length.has(l.symbol); });
        // Known when its expanded form is one met before (equal expanded forms: the difference
        // expands to zero).
        if (!turning && ctx.strand_lengths_expanded.insert(seg.length.expand()).second)
          ctx.m.strand_lengths.emplace_back(seg.length, "strand " + ctx.m.points[seg.from].name + "-" +
                                                            ctx.m.points[seg.to].name + " of " + in.label);
      }
  }
  return cached->second ? &*cached->second : nullptr;
}

}  // namespace tackle::build
