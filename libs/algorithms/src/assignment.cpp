#include "kestrel/algorithms/assignment.hpp"

#include <algorithm>
#include <cmath>

namespace kestrel::algorithms {

namespace {

// Hungarian method with potentials on an n x n matrix (rows <= columns after padding), O(n^3).
// Returns, for each row, its column.
std::vector<int> hungarian_square(const std::vector<std::vector<double>>& a) {
  const int n = static_cast<int>(a.size());
  const double inf = std::numeric_limits<double>::infinity();
  std::vector<double> u(static_cast<std::size_t>(n + 1)), v(static_cast<std::size_t>(n + 1));
  std::vector<int> p(static_cast<std::size_t>(n + 1)), way(static_cast<std::size_t>(n + 1));
  for (int i = 1; i <= n; ++i) {
    p[0] = i;
    int j0 = 0;
    std::vector<double> minv(static_cast<std::size_t>(n + 1), inf);
    std::vector<char> used(static_cast<std::size_t>(n + 1), 0);
    do {
      used[static_cast<std::size_t>(j0)] = 1;
      const int i0 = p[static_cast<std::size_t>(j0)];
      double delta = inf;
      int j1 = 0;
      for (int j = 1; j <= n; ++j) {
        if (used[static_cast<std::size_t>(j)]) continue;
        const double cur = a[static_cast<std::size_t>(i0 - 1)][static_cast<std::size_t>(j - 1)] -
                           u[static_cast<std::size_t>(i0)] - v[static_cast<std::size_t>(j)];
        if (cur < minv[static_cast<std::size_t>(j)]) {
          minv[static_cast<std::size_t>(j)] = cur;
          way[static_cast<std::size_t>(j)] = j0;
        }
        if (minv[static_cast<std::size_t>(j)] < delta) {
          delta = minv[static_cast<std::size_t>(j)];
          j1 = j;
        }
      }
      for (int j = 0; j <= n; ++j) {
        if (used[static_cast<std::size_t>(j)]) {
          u[static_cast<std::size_t>(p[static_cast<std::size_t>(j)])] += delta;
          v[static_cast<std::size_t>(j)] -= delta;
        } else {
          minv[static_cast<std::size_t>(j)] -= delta;
        }
      }
      j0 = j1;
    } while (p[static_cast<std::size_t>(j0)] != 0);
    do {
      const int j1 = way[static_cast<std::size_t>(j0)];
      p[static_cast<std::size_t>(j0)] = p[static_cast<std::size_t>(j1)];
      j0 = j1;
    } while (j0 != 0);
  }
  std::vector<int> row_to_col(static_cast<std::size_t>(n), -1);
  for (int j = 1; j <= n; ++j)
    if (p[static_cast<std::size_t>(j)] > 0)
      row_to_col[static_cast<std::size_t>(p[static_cast<std::size_t>(j)] - 1)] = j - 1;
  return row_to_col;
}

}  // namespace

Assignment solve_assignment(const Eigen::MatrixXd& cost, double gate) {
  const int rows = static_cast<int>(cost.rows());
  const int cols = static_cast<int>(cost.cols());
  Assignment result;
  result.row_to_col.assign(static_cast<std::size_t>(rows), -1);
  result.col_to_row.assign(static_cast<std::size_t>(cols), -1);
  if (rows == 0 || cols == 0) return result;

  auto allowed = [&](int r, int c) { return std::isfinite(cost(r, c)) && cost(r, c) <= gate; };
  // A forbidden pair costs more than every allowed pair together, so the solver only uses one
  // when no assignment with more allowed pairs exists; such pairs are then dropped.
  double total_allowed = 0.0, lowest = 0.0;
  for (int r = 0; r < rows; ++r)
    for (int c = 0; c < cols; ++c)
      if (allowed(r, c)) {
        total_allowed += std::abs(cost(r, c));
        lowest = std::min(lowest, cost(r, c));
      }
  const double forbidden = 2.0 * total_allowed + 1.0;

  const int n = std::max(rows, cols);
  std::vector<std::vector<double>> square(static_cast<std::size_t>(n),
                                          std::vector<double>(static_cast<std::size_t>(n), 0.0));
  for (int r = 0; r < rows; ++r)
    for (int c = 0; c < cols; ++c)
      square[static_cast<std::size_t>(r)][static_cast<std::size_t>(c)] =
          allowed(r, c) ? cost(r, c) - lowest : forbidden;

  const auto row_to_col = hungarian_square(square);
  for (int r = 0; r < rows; ++r) {
    const int c = row_to_col[static_cast<std::size_t>(r)];
    if (c < 0 || c >= cols || !allowed(r, c)) continue;
    result.row_to_col[static_cast<std::size_t>(r)] = c;
    result.col_to_row[static_cast<std::size_t>(c)] = r;
    result.total_cost += cost(r, c);
    ++result.pairs;
  }
  return result;
}

}  // namespace kestrel::algorithms
