#include "algebra/linear.hpp"

#include <algorithm>

namespace tackle {

using namespace GiNaC;

bool Tolerance::negligible(const numeric& x, const numeric& scale) const {
  if (x.is_zero()) return true;
  if (x.is_rational()) return false;
  return abs(x) <= relative * scale;
}

bool all_rational(const std::vector<Row>& rows) {
  return std::all_of(rows.begin(), rows.end(),
                     [](const Row& r) { return std::all_of(r.begin(), r.end(), [](const numeric& x) { return x.is_rational(); }); });
}

namespace {

// The reduced row echelon form: each pivot 1, the only entry in its column.
struct Echelon {
  std::vector<Row> rows;
  std::vector<std::size_t> pivots;  // each row's pivot column
};

numeric largest(const std::vector<Row>& rows) {
  numeric m = 0;
  for (const Row& r : rows)
    for (const numeric& x : r) m = std::max(m, abs(x));
  return m;
}

// The row at or below `from` to pivot on in column c: exact, the first not zero; floats, the
// largest, unless it is negligible. None: rows.size().
std::size_t pivot_row(const std::vector<Row>& a, std::size_t from, std::size_t c, bool exact, const numeric& scale,
                      const Tolerance& tolerance) {
  std::size_t best = a.size();
  for (std::size_t i = from; i < a.size(); ++i) {
    if (exact) {
      if (!a[i][c].is_zero()) return i;
      continue;
    }
    if (tolerance.negligible(a[i][c], scale)) continue;
    if (best == a.size() || abs(a[i][c]) > abs(a[best][c])) best = i;
  }
  return best;
}

Echelon reduce(std::vector<Row> a, std::size_t columns, const Tolerance& tolerance) {
  const bool exact = all_rational(a);
  const numeric scale = exact ? numeric(1) : largest(a);
  Echelon out;
  std::size_t r = 0;
  for (std::size_t c = 0; c < columns && r < a.size(); ++c) {
    const std::size_t p = pivot_row(a, r, c, exact, scale, tolerance);
    if (p == a.size()) continue;
    std::swap(a[r], a[p]);
    const numeric inverse = a[r][c].inverse();
    for (numeric& x : a[r]) x = x * inverse;
    for (std::size_t i = 0; i < a.size(); ++i) {
      if (i == r || a[i][c].is_zero()) continue;
      const numeric f = a[i][c];
      for (std::size_t j = 0; j < columns; ++j) a[i][j] = a[i][j] - f * a[r][j];
      a[i][c] = 0;
    }
    out.pivots.push_back(c);
    ++r;
  }
  a.resize(r);
  out.rows = std::move(a);
  return out;
}

}  // namespace

std::vector<Row> null_space(const std::vector<Row>& rows, std::size_t columns, const Tolerance& tolerance) {
  const Echelon e = reduce(rows, columns, tolerance);
  std::vector<bool> pivot(columns, false);
  for (const std::size_t c : e.pivots) pivot[c] = true;
  std::vector<Row> basis;
  for (std::size_t f = 0; f < columns; ++f) {
    if (pivot[f]) continue;
    Row x(columns, 0);
    x[f] = 1;
    for (std::size_t j = 0; j < e.rows.size(); ++j) x[e.pivots[j]] = -e.rows[j][f];
    basis.push_back(std::move(x));
  }
  return basis;
}

numeric dot(const Row& v, const Row& x) {
  numeric s = 0;
  for (std::size_t i = 0; i < v.size() && i < x.size(); ++i)
    if (!v[i].is_zero() && !x[i].is_zero()) s = s + v[i] * x[i];
  return s;
}

numeric size_of(const Row& v) {
  numeric s = 0;
  for (const numeric& x : v) s = s + abs(x);
  return s;
}

bool orthogonal(const Row& v, const Row& x, const Tolerance& tolerance) {
  // (Against the vectors' sizes, not the products': a float that is a zero up to rounding,
  // alone in a product, is as large as the product.)
  return tolerance.negligible(dot(v, x), size_of(v) * size_of(x));
}

bool proportional(const Row& v, const Row& w, const Tolerance& tolerance) {
  const numeric sv = size_of(v), sw = size_of(w);
  if (sv.is_zero() || sw.is_zero()) return false;
  const numeric scale = sv * sw;
  for (std::size_t i = 0; i < v.size(); ++i)
    for (std::size_t j = i + 1; j < v.size(); ++j)
      if (!tolerance.negligible(v[i] * w[j] - v[j] * w[i], scale)) return false;
  return true;
}

std::optional<Row> combination_of(const std::vector<Row>& rows, const Row& v, const Tolerance& tolerance) {
  // The columns of [rows^T | v], reduced: v is a combination when no pivot is in the last.
  const std::size_t k = rows.size();
  std::vector<Row> a(v.size(), Row(k + 1, 0));
  for (std::size_t i = 0; i < v.size(); ++i) {
    for (std::size_t j = 0; j < k; ++j) a[i][j] = j < rows.size() && i < rows[j].size() ? rows[j][i] : numeric(0);
    a[i][k] = v[i];
  }
  const Echelon e = reduce(std::move(a), k + 1, tolerance);
  Row lambda(k, 0);
  for (std::size_t j = 0; j < e.rows.size(); ++j) {
    if (e.pivots[j] == k) return std::nullopt;
    lambda[e.pivots[j]] = e.rows[j][k];
  }
  return lambda;
}

}  // namespace tackle
