// Sparse elimination of a linear system over rational functions: the one elimination the
// solver uses. Rows are sparse (a column appears in a row only while its entry is nonzero,
// decided exactly: a normal form, found without a gcd where the denominators are products of
// known irreducible factors, and sin^2 + cos^2 = 1), pivots are chosen by Markowitz's rule
// (fewest other entries in the pivot's row times its column, then the smallest entry), so a
// chain of bodies eliminates with O(1) fill per pivot instead of touching every row, and the
// solution is found by back substitution.
//
// With `Pivoting::in_column_order` the pivot column is always the first one left, so the
// columns without a pivot (the free unknowns) are those whose column lies in the span of
// the columns before it: the choice a person makes reading the unknowns in order, the same
// for every row order.
#pragma once

#include <cstddef>
#include <map>
#include <vector>

#include <ginac/ginac.h>

#include "expr/rational.hpp"

namespace tackle {

/// A x = b with A sparse: one map column -> nonzero coefficient per row.
struct SparseSystem {
  std::size_t columns = 0;
  std::vector<std::map<std::size_t, GiNaC::ex>> a;
  std::vector<GiNaC::ex> b;
};

enum class Pivoting { markowitz, in_column_order };

struct Elimination {
  std::size_t rank = 0;
  std::vector<bool> pivot;  // per column: has a pivot (else the column is free)
  /// Per pivot column: its value in terms of the right-hand sides' symbols and the free
  /// columns' symbols (normal form). Empty for free columns.
  std::vector<GiNaC::ex> value;
  /// Rows left without a pivot (each reads 0 = rhs): their index, the reduced right-hand
  /// side and, when tracked, the original rows they combine (in order).
  struct Leftover {
    std::size_t row = 0;
    GiNaC::ex rhs;
    std::vector<std::size_t> combination;
  };
  std::vector<Leftover> leftover;
};

/// Eliminates `s`. `symbols[j]` stands for column j in the values of the other columns when
/// column j is free. `track`: record, for each row left over, which original rows it combines.
/// Those are found by replaying the pivots in exact numbers at a random point of integers
/// (the rows a leftover row combines are those whose coefficient is not zero there; a
/// coefficient that is not zero vanishes at such a point with a chance of its degree over
/// 2^40), and symbolically when the entries are not all rational functions.
[[nodiscard]] Elimination eliminate(const SparseSystem& s, const std::vector<GiNaC::ex>& symbols, Pivoting pivoting,
                                    bool track);

}  // namespace tackle
