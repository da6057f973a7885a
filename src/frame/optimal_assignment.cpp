#include "emit/frame/optimal_assignment.hpp"

#include <limits>
#include <string>

#include "emit/core/errors.hpp"

namespace emit {

void OptimalAssignment::reserve(int max_rows, int max_cols) {
  max_rows_ = max_rows, max_cols_ = max_cols;
  const auto rows = static_cast<std::size_t>(max_rows) + 1, cols = static_cast<std::size_t>(max_cols) + 1;
  u_.assign(rows, 0);
  v_.assign(cols, 0);
  min_slack_.assign(cols, 0);
  column_row_.assign(cols, 0);
  previous_column_.assign(cols, 0);
  used_.assign(cols, 0);
  row_column_.assign(rows, 0);
}

// Index 0 is a virtual column (and row) that each augmentation starts from: rows and columns are
// numbered from 1 inside. u, v are the dual potentials (u_r + v_c ≤ cost(r, c), equality on the
// assignment); each row in turn is added by Dijkstra's shortest augmenting path over reduced costs.
std::span<const int> OptimalAssignment::solve(std::span<const double> cost, int rows, int cols) {
  if (rows < 0 || rows > cols || rows > max_rows_ || cols > max_cols_ ||
      cost.size() < static_cast<std::size_t>(rows) * static_cast<std::size_t>(cols))
    throw InvalidInput("OptimalAssignment::solve: a " + std::to_string(rows) + " x " + std::to_string(cols) +
                       " problem beyond its reserve or with more rows than columns");
  constexpr double infinity = std::numeric_limits<double>::infinity();
  const auto at = [&](int r, int c) {
    return cost[static_cast<std::size_t>(r - 1) * static_cast<std::size_t>(cols) + static_cast<std::size_t>(c - 1)];
  };
  for (int i = 0; i <= rows; ++i) u_[i] = 0;
  for (int j = 0; j <= cols; ++j) v_[j] = 0, column_row_[j] = 0;
  for (int r = 1; r <= rows; ++r) {
    column_row_[0] = r;
    int j0 = 0;
    for (int j = 0; j <= cols; ++j) min_slack_[j] = infinity, used_[j] = 0;
    do {
      used_[j0] = 1;
      const int i0 = column_row_[j0];
      double delta = infinity;
      int j1 = 0;
      for (int j = 1; j <= cols; ++j) {
        if (used_[j]) continue;
        const double reduced = at(i0, j) - u_[i0] - v_[j];
        if (reduced < min_slack_[j]) min_slack_[j] = reduced, previous_column_[j] = j0;
        if (min_slack_[j] < delta) delta = min_slack_[j], j1 = j;
      }
      for (int j = 0; j <= cols; ++j)
        if (used_[j]) {
          u_[column_row_[j]] += delta, v_[j] -= delta;
        } else {
          min_slack_[j] -= delta;
        }
      j0 = j1;
    } while (column_row_[j0] != 0);
    do {  // flip the augmenting path
      const int j1 = previous_column_[j0];
      column_row_[j0] = column_row_[j1];
      j0 = j1;
    } while (j0 != 0);
  }
  total_ = 0;
  for (int j = 1; j <= cols; ++j)
    if (column_row_[j] != 0) {
      row_column_[column_row_[j] - 1] = j - 1;
      total_ += at(column_row_[j], j);
    }
  return {row_column_.data(), static_cast<std::size_t>(rows)};
}

}  // namespace emit
