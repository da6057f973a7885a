// The live baseline: an exact mean at capture, slow drift followed while untouched, frozen while touched.
#include "emit/live/baseline.hpp"

#include <cmath>

#include <gtest/gtest.h>

#include "emit/core/errors.hpp"
#include "emit/live/latency_stats.hpp"

namespace emit {
namespace {

Frame constant_frame(double volts) { return Frame::Constant(4, 4, volts); }

// The mean of 1, 2, 3, 4 V is 2.5 V; sums of four small integers are exact in doubles.
TEST(Baseline, CaptureIsTheMeanOfTheFirstFrames) {
  BaselineOptions options;
  options.capture_frames = 4;
  Baseline baseline(options);
  EXPECT_TRUE(baseline.capturing());
  EXPECT_FALSE(baseline.ready());
  for (int k = 1; k <= 3; ++k) EXPECT_FALSE(baseline.capture(constant_frame(k)));
  EXPECT_TRUE(baseline.capture(constant_frame(4)));
  EXPECT_FALSE(baseline.capturing());
  EXPECT_EQ(baseline.captures(), 1u);
  EXPECT_EQ(baseline.reference(), constant_frame(2.5));
}

// V_ref ← V_ref + r (V − V_ref): after n untouched frames at V the gap is (1 − r)^n of the start's.
TEST(Baseline, FollowsDriftWhileUntouched) {
  BaselineOptions options;
  options.capture_frames = 1;
  options.drift_rate = 0.1;
  Baseline baseline(options);
  baseline.capture(constant_frame(1.0));
  for (int n = 0; n < 10; ++n) EXPECT_TRUE(baseline.follow(constant_frame(2.0), false));
  const double expected = 2.0 - std::pow(0.9, 10);           // gap of 1 V shrunk by 0.9 ten times
  EXPECT_NEAR(baseline.reference()(1, 2), expected, 1e-14);  // ten multiply-adds: a few ulps
}

TEST(Baseline, FrozenWhileTouched) {
  BaselineOptions options;
  options.capture_frames = 2;
  Baseline baseline(options);
  baseline.capture(constant_frame(1.0));
  baseline.capture(constant_frame(1.0));
  for (int n = 0; n < 100; ++n) EXPECT_FALSE(baseline.follow(constant_frame(3.0), true));
  EXPECT_EQ(baseline.reference(), constant_frame(1.0));
}

TEST(Baseline, RecaptureReplacesTheReference) {
  BaselineOptions options;
  options.capture_frames = 2;
  Baseline baseline(options);
  baseline.capture(constant_frame(1.0));
  baseline.capture(constant_frame(1.0));
  baseline.recapture();
  EXPECT_TRUE(baseline.capturing());
  EXPECT_TRUE(baseline.ready());  // the old reference stays until the new one is complete
  baseline.capture(constant_frame(5.0));
  EXPECT_EQ(baseline.reference(), constant_frame(1.0));
  baseline.capture(constant_frame(7.0));
  EXPECT_EQ(baseline.reference(), constant_frame(6.0));
  EXPECT_EQ(baseline.captures(), 2u);
}

TEST(Baseline, RejectsBadOptionsAndSizes) {
  EXPECT_THROW(Baseline(BaselineOptions{0, 0.01}), InvalidInput);
  EXPECT_THROW(Baseline(BaselineOptions{1, 1.5}), InvalidInput);
  Baseline baseline(BaselineOptions{1, 0.01});
  EXPECT_THROW(baseline.follow(constant_frame(1), false), InvalidInput);  // nothing captured yet
  baseline.capture(constant_frame(1));
  EXPECT_THROW(baseline.follow(Frame::Zero(3, 3), false), InvalidInput);
}

// 1..100 ms in 1 ms steps: the mean is 50.5 ms; the 95th value is 95 ms, resolved to one 50 µs bin.
TEST(LatencyStats, MeanAndQuantileToWithinABin) {
  LatencyStats stats;
  for (int k = 1; k <= 100; ++k) stats.add(1e-3 * k);
  EXPECT_EQ(stats.count(), 100u);
  EXPECT_NEAR(stats.mean_s(), 50.5e-3, 1e-12);
  EXPECT_NEAR(stats.quantile_s(0.95), 95e-3, 1.5 * LatencyStats::bin_s);  // a value on a bin edge may land either side
  EXPECT_DOUBLE_EQ(stats.max_s(), 0.1);
  EXPECT_DOUBLE_EQ(stats.quantile_s(1.0), 0.1);
}

}  // namespace
}  // namespace emit
