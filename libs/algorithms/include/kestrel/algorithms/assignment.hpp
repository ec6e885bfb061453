#pragma once
// Optimal rectangular assignment (the linear sum assignment problem), solved by the Hungarian
// method. The one solver of the project: the detection evaluator, the MOT evaluator and the
// trackers' associators all call it.
#include <Eigen/Core>
#include <limits>
#include <vector>

namespace kestrel::algorithms {

struct Assignment {
  std::vector<int> row_to_col;  ///< -1: row unassigned
  std::vector<int> col_to_row;  ///< -1: column unassigned
  double total_cost = 0.0;      ///< over assigned pairs
  int pairs = 0;
};

/// Forbidden pairs are marked with this cost (or anything not finite).
inline constexpr double kForbidden = std::numeric_limits<double>::infinity();

/// Assigns rows to columns. Pairs with a non-finite cost, or a cost above `gate`, are never
/// assigned. Among the assignments with the most pairs, returns one of least total cost (as
/// scipy's linear_sum_assignment does once invalid pairs are given a prohibitive cost).
Assignment solve_assignment(const Eigen::MatrixXd& cost, double gate = std::numeric_limits<double>::infinity());

}  // namespace kestrel::algorithms
