// The assignment problem: rows matched to columns for the largest total value (a student's
// arrows to the model's forces, in check/fbd_grade.cpp).
#pragma once

#include <cstddef>
#include <vector>

namespace tackle {

/// The assignment of rows to columns with the largest total value, by the Hungarian method
/// (O(n^3); a free body diagram has at most 60 arrows): the column of each row, or -1 for a
/// row left without one (more rows than columns, or only pairs of value 0 or less).
[[nodiscard]] std::vector<int> best_assignment(const std::vector<std::vector<double>>& value, std::size_t columns);

}  // namespace tackle
