// A path: points in order, the one place where the geometry of strings, cables, springs and
// dampers lives. Its segments' lengths and unit directions, its length and the loads a
// tension along it exerts all derive from it (the split of SymPy mechanics' pathways and
// actuators). Sign convention, once: a positive tension pulls each end of every segment
// towards the segment's other end; a path's length grows when its ends move apart.
#pragma once

#include <functional>
#include <optional>
#include <string>
#include <vector>

#include <ginac/ginac.h>

#include "core/diagnostics.hpp"
#include "model/load_origin.hpp"
#include "model/vec.hpp"

namespace tackle {

struct Body;
struct Point;
struct Load;

struct PathSegment {
  int from = -1, to = -1;      // indices into the model's points
  GiNaC::ex length;            // exact and positive in the layout (|to - from|, simplified)
  Vec direction = zero_vec();  // unit vector from `from` towards `to`
  bool constant = false;       // both ends on one body, or both fixed: its length never changes
};

struct Path {
  std::vector<int> points;
  std::vector<PathSegment> segments;
  GiNaC::ex length = 0;          // every segment
  GiNaC::ex varying_length = 0;  // the segments that change (the constant ones drop out)
};

/// Names the length of a strand that turns as the bodies move: given the strand's ends and
/// its squared length (a polynomial), returns the positive symbol that stands for the root.
using NameTurningLength = std::function<GiNaC::ex(const Point& from, const Point& to, const GiNaC::ex& squared)>;

/// The root of a perfect square (a positive numeric times even powers, of symbols or of
/// functions such as sin(theta)), its sign as the powers' halves give it; or nothing.
[[nodiscard]] std::optional<GiNaC::ex> square_root_of(const GiNaC::ex& squared);

/// The path through `indices` in a problem with `dims` axes. A segment's length is
/// |to - from| simplified (perfect squares come out of the root, sin^2 + cos^2 = 1), its sign
/// and non-zero length decided by `layout` (parameter values and the layout's coordinates).
/// A length that stays a root of the coordinates is named by `turning` (a symbol, never the
/// root itself). Problems go to `diags` at `at`, naming the segment as "A-B of <label>".
[[nodiscard]] std::optional<Path> make_path(const std::vector<int>& indices, const std::vector<Point>& points, int dims,
                                            const GiNaC::exmap& layout, Diagnostics& diags, const Location& at,
                                            const std::string& label, const NameTurningLength& turning);

/// The loads of a tension along the path: at each end (on a body) of each changing segment,
/// `tension` times the unit vector towards the other end. Each load's origin is a strand of
/// the connection `of` comes from.
[[nodiscard]] std::vector<Load> tension_loads(const Path& p, const std::vector<Point>& points, const GiNaC::ex& tension,
                                              const LoadOrigin& of);

}  // namespace tackle
