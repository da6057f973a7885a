#include "emit/live/latency_stats.hpp"

#include <gtest/gtest.h>

namespace emit {
namespace {

// 1 ms … 100 ms in 1 ms steps: the 95th of 100 is 95 ms, to within a bin (the bin's upper edge).
TEST(LatencyStats, QuantilesToWithinABin) {
  LatencyStats stats;
  for (int i = 1; i <= 100; ++i) stats.add(i * 1e-3 - 1e-6);
  EXPECT_NEAR(stats.mean_s(), 50.5e-3 - 1e-6, 1e-12);
  EXPECT_NEAR(stats.quantile_s(0.95), 95e-3, LatencyStats::bin_s);
  EXPECT_NEAR(stats.quantile_s(0.5), 50e-3, LatencyStats::bin_s);
  EXPECT_DOUBLE_EQ(stats.quantile_s(1.0), stats.max_s());
}

// Latencies beyond the histogram's range (a slow machine: seconds a frame) are not reported as the
// range's end: a p95 among 3-8 s latencies is no less than the mean of the fastest 95 % of them.
TEST(LatencyStats, BeyondTheRangeTheQuantileIsTheLargestSeen) {
  LatencyStats stats;
  for (int i = 0; i < 20; ++i) stats.add(3.0 + 0.25 * i);
  EXPECT_GT(stats.quantile_s(0.95), LatencyStats::range_s);
  EXPECT_GE(stats.quantile_s(0.95), stats.mean_s());
  EXPECT_DOUBLE_EQ(stats.quantile_s(0.95), stats.max_s());
}

}  // namespace
}  // namespace emit
