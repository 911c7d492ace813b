// The paths of connections (strings, springs, dampers): made once per points argument, with
// a positive length symbol for each strand that turns as the bodies move.
#include "model/builder/stages.hpp"

#include <algorithm>

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

}  // namespace

// The path of a points argument, made on first use; nothing when it cannot be made (its
// problems are reported then).
const Path* path_of(BuildContext& ctx, Instance& in, const std::string& key) {
  auto it = in.path_args.find(key);
  if (it == in.path_args.end()) return nullptr;
  // A body whose coordinate could not be made has been reported already.
  for (int p : it->second)
    if (ctx.m.dims() == 1 && ctx.m.points[p].body >= 0 && ctx.m.bodies[ctx.m.points[p].body].coord.is_zero()) return nullptr;
  auto [cached, fresh] = in.paths.try_emplace(key);
  if (fresh) {
    cached->second = make_path(it->second, ctx.m.points, ctx.m.dims(), ctx.layout, ctx.diags, in.c.at, in.label,
                               [&ctx](const Point& a, const Point& b, const ex& squared) { return turning_length(ctx, a, b, squared); });
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
        const bool known = std::any_of(ctx.m.strand_lengths.begin(), ctx.m.strand_lengths.end(),
                                       [&](const auto& s) { return (s.first - seg.length).expand().is_zero(); });
        if (!turning && !known)
          ctx.m.strand_lengths.emplace_back(seg.length, "strand " + ctx.m.points[seg.from].name + "-" +
                                                            ctx.m.points[seg.to].name + " of " + in.label);
      }
  }
  return cached->second ? &*cached->second : nullptr;
}

}  // namespace tackle::build
