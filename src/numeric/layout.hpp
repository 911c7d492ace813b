// The numbers a mechanism is drawn at: its sketch, its free body diagrams, and the student's
// diagram compared with them.
#pragma once

#include <array>
#include <functional>
#include <optional>
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

/// `e` at `values` as a real number, through the evaluation every stage uses (no pole reaches
/// GiNaC); none where it is undefined, not real or not finite.
[[nodiscard]] std::optional<double> real_at(const GiNaC::ex& e, const GiNaC::exmap& values);

/// A point's coordinates by `number` (one per axis of `m`, the rest 0); none when one cannot be
/// evaluated.
[[nodiscard]] std::optional<std::array<double, 3>> point_at(
    const Model& m, const std::function<std::optional<double>(const GiNaC::ex&)>& number, const Vec& v);

}  // namespace tackle
