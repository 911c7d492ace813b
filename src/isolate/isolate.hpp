// Isolating one unknown: search the problem's points and axes for a single balance equation
// (LMB along a direction, or AMB about a point along an axis) that contains that unknown and
// no other. This is the book's "AMB about axis OG gives T in one equation", done by search.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include <ginac/ginac.h>

#include "equations/equations.hpp"
#include "model/model.hpp"

namespace tackle {

struct Isolation {
  GiNaC::ex unknown;
  std::optional<Equation> equation;  // the first equation found that has the unknown alone
  std::optional<GiNaC::ex> value;    // the unknown solved from it
  std::size_t tried = 0;             // how many candidate equations were looked at
  // In 2-D and 3-D the search is complete for the balances of one body: when no equation is
  // found, `impossible` says that no combination of one body's balances has it alone.
  bool impossible = false;
};

/// The candidate equations, in the order they are tried: LMB along the coordinate axes,
/// then along the lines between points (and, in 2-D, across them); AMB about each point (in
/// 3-D along the coordinate axes and along the line to each other point); in 1-D the
/// constraints as well.
[[nodiscard]] std::vector<Equation> candidate_equations(const Model& m);

/// The unknowns of a model: the body accelerations not given and the rules' unknowns.
[[nodiscard]] std::vector<GiNaC::ex> model_unknowns(const Model& m);

/// First the named candidates; then, in 2-D and 3-D, the exact test: the unknown's column in
/// a body's balance components (LMB, and AMB about the origin) must lie outside the span of
/// the other unknowns' columns; a null-space vector gives the combination, reported as LMB
/// along a direction or AMB about a point along an axis.
[[nodiscard]] Isolation isolate(const Model& m, const std::vector<Equation>& candidates, const GiNaC::ex& unknown);

}  // namespace tackle
