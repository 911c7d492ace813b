// A plot's data: curves over one variable (a sweep of a parameter, or a motion in time), each
// point marked valid or not. The writers draw it (pgfplots in LaTeX, SVG elsewhere).
#pragma once

#include <optional>
#include <string>
#include <vector>

namespace tackle {

struct SweepResult {
  std::string title;
  std::string x_name, x_unit;  // the horizontal axis: "h" and "m", or "h/l" and ""
  std::string x_latex;         // the same in LaTeX
  // When the axis is an expression (`against`): the varied parameter's own values too.
  std::string varied_name, varied_unit;
  std::vector<double> varied;
  std::vector<std::string> names;  // one per plotted expression, as written
  std::vector<std::string> latex;  // the same in LaTeX
  std::string y_unit;              // when every curve has the same dimension
  std::vector<std::string> units;  // each curve's SI unit ("" when it has none or it is unknown)
  std::vector<double> x;
  std::vector<std::vector<std::optional<double>>> y;  // [curve][point]
  std::vector<bool> valid;                            // every validity condition holds
  // Where the validity changes between two samples, the point where the failing condition
  // reaches its bound: the solid part ends and the dashed part begins there. It is a sample
  // when the bound falls on one, else a point put in between (not a sample: the CSV leaves it
  // out). Empty: no such points.
  std::vector<bool> boundary, inserted;
  [[nodiscard]] bool is_boundary(std::size_t i) const { return i < boundary.size() && boundary[i]; }
  [[nodiscard]] bool is_inserted(std::size_t i) const { return i < inserted.size() && inserted[i]; }
};

}  // namespace tackle
