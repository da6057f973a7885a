// The assignment solver against brute force: every permutation of columns tried on small random
// problems gives the same least total cost.
#include "emit/frame/optimal_assignment.hpp"

#include <algorithm>
#include <numeric>
#include <random>
#include <vector>

#include <gtest/gtest.h>

#include "allocation_counter.hpp"
#include "test_support.hpp"

namespace emit {
namespace {

/// The least total over every injective map of rows to columns (each a prefix of a permutation).
double brute_force(const std::vector<double>& cost, int rows, int cols) {
  std::vector<int> columns(static_cast<std::size_t>(cols));
  std::iota(columns.begin(), columns.end(), 0);
  double best = 1e300;
  do {
    double total = 0;
    for (int r = 0; r < rows; ++r)
      total += cost[static_cast<std::size_t>(r) * static_cast<std::size_t>(cols) +
                    static_cast<std::size_t>(columns[static_cast<std::size_t>(r)])];
    best = std::min(best, total);
  } while (std::next_permutation(columns.begin(), columns.end()));
  return best;
}

TEST(OptimalAssignment, MatchesBruteForceOnRandomProblems) {
  std::mt19937_64 rng(5);
  OptimalAssignment solver;
  solver.reserve(6, 7);
  for (int trial = 0; trial < 300; ++trial) {
    const int cols = 1 + static_cast<int>(rng() % 7),
              rows = static_cast<int>(rng() % static_cast<unsigned>(std::min(cols, 6) + 1));
    std::vector<double> cost(static_cast<std::size_t>(rows * cols));
    for (double& c : cost) c = std::uniform_real_distribution<double>(0, 10)(rng);
    if (trial % 3 == 0)  // ties: integer costs
      for (double& c : cost) c = std::floor(c / 3);
    const auto column = solver.solve(cost, rows, cols);
    std::vector<int> seen;
    double total = 0;
    for (int r = 0; r < rows; ++r) {
      const int c = column[static_cast<std::size_t>(r)];
      ASSERT_GE(c, 0);
      ASSERT_LT(c, cols);
      seen.push_back(c);
      total += cost[static_cast<std::size_t>(r) * static_cast<std::size_t>(cols) + static_cast<std::size_t>(c)];
    }
    std::sort(seen.begin(), seen.end());
    EXPECT_EQ(std::adjacent_find(seen.begin(), seen.end()), seen.end()) << "a column used twice";
    // Sums of at most 6 terms of size 10: a few ulps of 60.
    EXPECT_NEAR(total, brute_force(cost, rows, cols), 1e-12);
    EXPECT_NEAR(solver.total_cost(), total, 1e-12);
  }
}

TEST(OptimalAssignment, AllocatesNothingWithinItsReserveAndRefusesBeyondIt) {
  OptimalAssignment solver;
  solver.reserve(4, 8);
  const std::vector<double> cost{4, 1, 3, 2, 0, 5, 3, 2, 2};
  {
    const test::AllocationCounter counter;
    const auto column = solver.solve(cost, 3, 3);
    EXPECT_EQ(counter.count(), 0);
    EXPECT_EQ(solver.total_cost(), 5.0);  // 1 + 2 + 2 (the classic example's optimum)
    EXPECT_EQ(column[0], 1);
  }
  EXPECT_NE(test::error_of([&] { solver.solve(cost, 3, 2); }).find("more rows than columns"), std::string::npos);
  const std::vector<double> big(50, 1.0);
  EXPECT_NE(test::error_of([&] { solver.solve(big, 5, 9); }).find("beyond its reserve"), std::string::npos);
}

}  // namespace
}  // namespace emit
