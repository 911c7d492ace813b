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
  return std::all_of(rows.begin(), rows.end(), [](const Row& r) {
    return std::all_of(r.begin(), r.end(), [](const numeric& x) { return x.is_rational(); });
  });
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

namespace {

bool rational(const Row& v) {
  return std::all_of(v.begin(), v.end(), [](const numeric& x) { return x.is_rational(); });
}

}  // namespace

bool orthogonal(const Row& v, const Row& x, const Tolerance& tolerance) {
  const numeric d = dot(v, x);
  if (d.is_zero()) return true;
  if (rational(v) && rational(x)) return false;
  // (Against the vectors' sizes, not the products': a float that is a zero up to rounding,
  // alone in a product, is as large as the product.)
  return tolerance.negligible(d, size_of(v) * size_of(x));
}

bool proportional(const Row& v, const Row& w, const Tolerance& tolerance) {
  // w = r v, r = w_i / v_i at v's first entry that is not zero: each minor with that entry.
  std::size_t i = 0;
  while (i < v.size() && v[i].is_zero()) ++i;
  if (i == v.size() || i >= w.size()) return false;
  const bool exact = rational(v) && rational(w);
  const numeric scale = exact ? numeric(1) : size_of(v) * size_of(w);
  if (scale.is_zero()) return false;
  for (std::size_t j = 0; j < v.size() && j < w.size(); ++j) {
    if (j == i) continue;
    const numeric minor = v[i] * w[j] - v[j] * w[i];
    if (exact ? !minor.is_zero() : !tolerance.negligible(minor, scale)) return false;
  }
  // (w all zero is no multiple: its entry at i must not be zero.)
  return exact ? !w[i].is_zero() : !tolerance.negligible(w[i], scale / size_of(v));
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

Row LeftInverse::coefficients(const Row& v) const {
  Row lambda(inverse.empty() ? 0 : inverse.front().size(), 0);
  for (std::size_t i = 0; i < columns.size(); ++i) {
    const numeric& x = v[columns[i]];
    if (x.is_zero()) continue;
    for (std::size_t j = 0; j < lambda.size(); ++j)
      if (!inverse[i][j].is_zero()) lambda[j] = lambda[j] + x * inverse[i][j];
  }
  return lambda;
}

std::optional<LeftInverse> left_inverse(const std::vector<Row>& rows, std::size_t columns, const Tolerance& tolerance) {
  const Echelon e = reduce(rows, columns, tolerance);
  if (e.rows.size() != rows.size()) return std::nullopt;
  // [M_P | I], reduced: [I | M_P^-1], with M_P the rows at the pivot columns (as columns of
  // the system lambda^T M_P = v_P: M_P^T lambda = v_P, so the inverse is of M_P).
  const std::size_t k = rows.size();
  std::vector<Row> a(k, Row(2 * k, 0));
  for (std::size_t i = 0; i < k; ++i) {
    for (std::size_t j = 0; j < k; ++j) a[i][j] = rows[i][e.pivots[j]];
    a[i][k + i] = 1;
  }
  const Echelon g = reduce(std::move(a), 2 * k, tolerance);
  if (g.rows.size() != k || (k > 0 && g.pivots.back() != k - 1)) return std::nullopt;
  LeftInverse out;
  out.columns = e.pivots;
  // M_P^-1 (k x k): row i of it is g.rows[i]'s right half; lambda_j = sum_i v_P[i] (M_P^-1)[i][j].
  out.inverse.assign(k, Row(k, 0));
  for (std::size_t i = 0; i < k; ++i)
    for (std::size_t j = 0; j < k; ++j) out.inverse[i][j] = g.rows[i][k + j];
  return out;
}

std::vector<std::size_t> independent_rows(const std::vector<Row>& rows, std::size_t columns,
                                          const Tolerance& tolerance) {
  // Each row reduced by those kept (each kept one with its pivot 1 and its pivot column
  // cleared from those kept after it): what is left not zero, it is kept.
  const bool exact = all_rational(rows);
  const numeric scale = exact ? numeric(1) : largest(rows);
  std::vector<std::size_t> out;
  std::vector<std::pair<std::size_t, Row>> kept;  // pivot column, row
  for (std::size_t i = 0; i < rows.size(); ++i) {
    Row r = rows[i];
    for (const auto& [c, b] : kept) {
      if (r[c].is_zero()) continue;
      const numeric f = r[c];
      for (std::size_t j = 0; j < columns; ++j) r[j] = r[j] - f * b[j];
      r[c] = 0;
    }
    std::size_t c = 0;
    for (std::size_t j = 1; j < columns; ++j)
      if (abs(r[j]) > abs(r[c])) c = j;
    if (columns == 0 || tolerance.negligible(r[c], scale) || r[c].is_zero()) continue;
    const numeric inverse = r[c].inverse();
    for (numeric& x : r) x = x * inverse;
    kept.emplace_back(c, std::move(r));
    out.push_back(i);
  }
  return out;
}

}  // namespace tackle
