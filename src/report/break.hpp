// Long equations broken as a book breaks them: at the top-level + and - of a sum, after the
// relation, the continuation lines indented. A single fraction whose numerator is the long
// part is written as 1/(denominator) times the numerator first, and a long sum in
// parentheses is broken inside them (\bigl( ... \bigr), as \left and \right cannot span
// lines). Works on the LaTeX that the print contexts write, so LaTeX and KaTeX agree.
#pragma once

#include <string>
#include <string_view>
#include <vector>

namespace tackle {

/// About how wide `tex` is when typeset, in characters of math at the text's size (a
/// fraction as wide as its wider part, scripts narrower, commands as what they show).
[[nodiscard]] double tex_width(std::string_view tex);

/// `rhs` in lines of at most about `width` characters: one line when it fits or cannot be
/// broken; else the first line, then lines that each begin with their operator ("+ ..."
/// or "- ...").
[[nodiscard]] std::vector<std::string> break_tex(const std::string& rhs, double width);

/// `lhs rel rhs tail` in display lines of about `width` characters: one line, as it is, when
/// it fits or cannot be broken; else rows aligned with `&` as break_tex breaks (a long left
/// side too, the relation then after it), `tail` (a number, a unit) at the end of the last.
[[nodiscard]] std::vector<std::string> displayed_lines(const std::string& lhs, const std::string& rel,
                                                       const std::string& rhs, const std::string& tail, double width);

/// The same as one formula: the line, or the rows in an `aligned` block (KaTeX, HTML).
[[nodiscard]] std::string displayed(const std::string& lhs, const std::string& rel, const std::string& rhs,
                                    const std::string& tail, double width);

/// Math set inline in a paragraph, made breakable where it is long: TeX breaks inline math
/// after a + or - at its top level only, so a long fraction becomes 1/(denominator) times
/// its numerator and \\left( \\right) plain parentheses (which make no group).
[[nodiscard]] std::string inline_tex(const std::string& tex);

}  // namespace tackle
