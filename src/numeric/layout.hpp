// The numbers a mechanism is drawn at: its sketch, its free body diagrams, and the student's
// diagram compared with them.
#pragma once

#include <set>

#include <ginac/ginac.h>

#include "model/model.hpp"

namespace tackle {

/// The numbers a free body diagram is drawn at: every parameter's value and the layout's
/// coordinates, with `values` (SI, by symbol: a variant's) over the parameters' own; a
/// parameter without a value as 1 (and put in `defaulted`), a coordinate the layout does not
/// place at 0; the defined parameters and turning lengths made from them.
[[nodiscard]] GiNaC::exmap layout_numbers(const Model& m, const GiNaC::exmap& values = {},
                                          std::set<GiNaC::ex, GiNaC::ex_is_less>* defaulted = nullptr);

}  // namespace tackle
