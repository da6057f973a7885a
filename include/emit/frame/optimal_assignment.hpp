#pragma once
/// \file optimal_assignment.hpp
/// The rectangular linear assignment problem: given a rows × cols cost matrix (rows ≤ cols), the
/// one-to-one assignment of every row to a distinct column of least total cost. The Hungarian
/// method in its shortest-augmenting-path form (Kuhn 1955, Munkres 1957; as Jonker & Volgenant
/// 1987 organise it): one augmentation per row, O(rows² · cols).
///
/// Written here because the libraries Debian ships either allocate on each call or solve it only
/// as a general linear programme; the contact tracker (contact_tracker.hpp) solves one small
/// problem per frame and must not allocate: reserve() sizes the scratch once, solve() then
/// allocates nothing for problems within it.
#include <span>
#include <vector>

namespace emit {

class OptimalAssignment {
 public:
  /// Scratch for problems up to max_rows × max_cols.
  void reserve(int max_rows, int max_cols);

  /// \param cost  rows × cols, row-major (cost[r·cols + c]), finite; 0 ≤ rows ≤ cols, within reserve().
  /// \return for each row its column, valid until the next call.
  /// \throw InvalidInput for rows > cols or a size beyond the reserve.
  std::span<const int> solve(std::span<const double> cost, int rows, int cols);

  /// The least total cost of the last solve().
  double total_cost() const { return total_; }

 private:
  std::vector<double> u_, v_, min_slack_;  ///< row and column potentials; per column, the least reduced cost to it
  std::vector<int> column_row_, previous_column_, row_column_;
  std::vector<char> used_;
  int max_rows_ = 0, max_cols_ = 0;
  double total_ = 0;
};

}  // namespace emit
