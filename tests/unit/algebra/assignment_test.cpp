// The assignment problem, against cases solved by hand (every assignment of a 3 x 3 listed).
#include <catch2/catch.hpp>

#include "algebra/assignment.hpp"

using tackle::best_assignment;

TEST_CASE("Assignment: the largest total, not the greedy choice", "[algebra][assignment]") {
  // Greedy takes row 0's 9 (column 0) and reaches 9 + 1 + 6 = 16; the best is 8 + 7 + 6 = 21
  // (rows 0, 1, 2 to columns 1, 0, 2), the largest of the six assignments (in the order
  // (0,1,2), (0,2,1), (1,0,2), (1,2,0), (2,0,1), (2,1,0): 16, 13, 21, 10, 11, 3).
  const std::vector<std::vector<double>> value{{9, 8, 1}, {7, 1, 1}, {1, 3, 6}};
  CHECK(best_assignment(value, 3) == std::vector<int>{1, 0, 2});
}

TEST_CASE("Assignment: more rows than columns leave a row without one, and so does a pair worth nothing",
          "[algebra][assignment]") {
  // Two rows, one column: the row of larger value gets it.
  CHECK(best_assignment({{2}, {5}}, 1) == std::vector<int>{-1, 0});
  // A row whose only pairs are worth 0 is left without a column.
  CHECK(best_assignment({{0, 0}, {0, 3}}, 2) == std::vector<int>{-1, 1});
  // Nothing to assign.
  CHECK(best_assignment({}, 3).empty());
  CHECK(best_assignment({{1, 2}}, 0) == std::vector<int>{-1});
}
