// The assignment problem (see assignment.hpp).
#include "algebra/assignment.hpp"

#include <algorithm>

namespace tackle {

std::vector<int> best_assignment(const std::vector<std::vector<double>>& value, std::size_t columns) {
  const std::size_t rows = value.size(), n = std::max(rows, columns);
  std::vector<int> out(rows, -1);
  if (rows == 0 || columns == 0) return out;
  // u, v: potentials; p[j]: the row matched to column j (1-based, 0: none).
  std::vector<double> u(n + 1, 0), v(n + 1, 0);
  std::vector<std::size_t> p(n + 1, 0), way(n + 1, 0);
  auto cost = [&](std::size_t i, std::size_t j) { return i < rows && j < columns ? -value[i][j] : 0.0; };
  for (std::size_t i = 1; i <= n; ++i) {
    p[0] = i;
    std::size_t j0 = 0;
    std::vector<double> minv(n + 1, 1e300);
    std::vector<char> used(n + 1, 0);
    do {
      used[j0] = 1;
      const std::size_t i0 = p[j0];
      double delta = 1e300;
      std::size_t j1 = 0;
      for (std::size_t j = 1; j <= n; ++j) {
        if (used[j]) continue;
        const double cur = cost(i0 - 1, j - 1) - u[i0] - v[j];
        if (cur < minv[j]) {
          minv[j] = cur;
          way[j] = j0;
        }
        if (minv[j] < delta) {
          delta = minv[j];
          j1 = j;
        }
      }
      for (std::size_t j = 0; j <= n; ++j) {
        if (used[j]) {
          u[p[j]] += delta;
          v[j] -= delta;
        } else {
          minv[j] -= delta;
        }
      }
      j0 = j1;
    } while (p[j0] != 0);
    do {
      const std::size_t j1 = way[j0];
      p[j0] = p[j1];
      j0 = j1;
    } while (j0 != 0);
  }
  for (std::size_t j = 1; j <= n; ++j)
    if (p[j] != 0 && p[j] - 1 < rows && j - 1 < columns && value[p[j] - 1][j - 1] > 0)
      out[p[j] - 1] = static_cast<int>(j - 1);
  return out;
}

}  // namespace tackle
