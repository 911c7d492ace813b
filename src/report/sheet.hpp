// Problem sheets: a description's `statement` with each {parameter} filled in, per variant, and
// what is asked; the variants are those of `tackle key` with the same seed.
#pragma once

#include <string>
#include <vector>

#include "report/derivation.hpp"
#include "report/key.hpp"

namespace tackle {

struct SheetEntry {
  const Derivation* derivation = nullptr;
  const Model* model = nullptr;   // its statement
  std::vector<Variant> variants;  // none: the description's own values
};

/// One sheet for every entry and variant (LaTeX document, Markdown or an HTML page); an entry
/// without a statement shows its title and what is asked. `figures`: each problem's drawn
/// free body diagrams under its statement (left out by default: they are part of the answer);
/// a 1-D or 2-D mechanism's sketch is always drawn there.
[[nodiscard]] std::string write_sheet(const std::vector<SheetEntry>& entries, Format f, bool figures = false);
/// The first problem of `e` as a sheet shows it, in HTML without its heading or the page around
/// it: the statement with its numbers (math for KaTeX), the mechanism's sketch, what is asked.
[[nodiscard]] std::string sheet_problem_html(const SheetEntry& e, bool figures = false);

}  // namespace tackle
