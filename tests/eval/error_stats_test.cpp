// Error summaries (eval/error_stats.hpp) against values worked by hand.
#include "emit/eval/error_stats.hpp"

#include <cmath>

#include <gtest/gtest.h>

namespace emit {
namespace {

// 1..5 (given out of order): mean 3, sample variance 10/4, median 3, and the 95th percentile
// interpolated between the 4th and 5th order statistics at 0.95·4 = 3.8: 4.8.
TEST(ErrorStats, MeanStdAndQuantilesOfOneToFive) {
  const ErrorStats s = summarize_errors({4, 1, 5, 3, 2}, 2);
  EXPECT_EQ(s.count, 5);
  EXPECT_EQ(s.missed, 2);
  EXPECT_DOUBLE_EQ(s.mean, 3.0);
  EXPECT_DOUBLE_EQ(s.std, std::sqrt(2.5));
  EXPECT_DOUBLE_EQ(s.median, 3.0);
  EXPECT_DOUBLE_EQ(s.p95, 4.8);
}

// One error: no spread (n − 1 = 0 is not divided by); none: all zero, the misses kept.
TEST(ErrorStats, OneValueAndNone) {
  const ErrorStats one = summarize_errors({0.7}, 0);
  EXPECT_EQ(one.count, 1);
  EXPECT_EQ(one.mean, 0.7);
  EXPECT_EQ(one.std, 0.0);
  EXPECT_EQ(one.median, 0.7);
  EXPECT_EQ(one.p95, 0.7);
  const ErrorStats none = summarize_errors({}, 4);
  EXPECT_EQ(none.count, 0);
  EXPECT_EQ(none.missed, 4);
  EXPECT_EQ(none.mean, 0.0);
}

// The strongest contact is the first; a 3-4-5 triangle gives exactly 5 mm.
TEST(ErrorStats, SinglePressErrorIsTheFirstContactsDistance) {
  Contact first, second;
  first.x_mm = 13, first.y_mm = 24;
  second.x_mm = 10, second.y_mm = 20;
  EXPECT_DOUBLE_EQ(single_press_error_mm({first, second}, Press{10, 20, 5, 1}), 5.0);
  EXPECT_LT(single_press_error_mm({}, Press{10, 20, 5, 1}), 0.0);
}

}  // namespace
}  // namespace emit
