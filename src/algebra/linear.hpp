// Linear algebra at one point: small dense matrices of numbers, exact rationals where every
// entry is one (each decision is then certain), else CLN floats with a relative tolerance (an
// entry whose size is below it, against the matrix's largest, counts as zero).
#pragma once

#include <optional>
#include <vector>

#include <ginac/ginac.h>

namespace tackle {

using Row = std::vector<GiNaC::numeric>;

/// What counts as zero among floats: |x| <= relative * scale.
struct Tolerance {
  GiNaC::numeric relative;
  [[nodiscard]] bool negligible(const GiNaC::numeric& x, const GiNaC::numeric& scale) const;
};

/// Whether every entry is an exact rational.
[[nodiscard]] bool all_rational(const std::vector<Row>& rows);

/// A basis of { x : rows x = 0 } (each vector as long as a row), by elimination; `columns`:
/// the rows' length (for an empty list of rows).
[[nodiscard]] std::vector<Row> null_space(const std::vector<Row>& rows, std::size_t columns,
                                          const Tolerance& tolerance);

/// The sum of the entries' sizes.
[[nodiscard]] GiNaC::numeric size_of(const Row& v);
/// v . x
[[nodiscard]] GiNaC::numeric dot(const Row& v, const Row& x);
/// Whether v . x is zero (exactly, or within the tolerance of sum |v_i x_i|).
[[nodiscard]] bool orthogonal(const Row& v, const Row& x, const Tolerance& tolerance);
/// Whether v is a multiple of w, both not zero (every 2x2 minor zero).
[[nodiscard]] bool proportional(const Row& v, const Row& w, const Tolerance& tolerance);
/// For rows that are independent: the columns P where they are (a square matrix, invertible)
/// and that matrix's inverse, so that a combination v of the rows has its coefficients
/// lambda = v_P inverse. None when the rows are not independent.
struct LeftInverse {
  std::vector<std::size_t> columns;
  std::vector<Row> inverse;
  /// lambda for v (meaningful only where v is a combination of the rows).
  [[nodiscard]] Row coefficients(const Row& v) const;
};
[[nodiscard]] std::optional<LeftInverse> left_inverse(const std::vector<Row>& rows, std::size_t columns,
                                                      const Tolerance& tolerance);
/// The rows (their places) that are independent, each one kept when it is not a combination
/// of those before it.
[[nodiscard]] std::vector<std::size_t> independent_rows(const std::vector<Row>& rows, std::size_t columns,
                                                        const Tolerance& tolerance);
/// Some lambda with sum lambda_i rows_i = v, or none when v is not a combination of the rows.
[[nodiscard]] std::optional<Row> combination_of(const std::vector<Row>& rows, const Row& v, const Tolerance& tolerance);

}  // namespace tackle
