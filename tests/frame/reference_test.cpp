// The no-contact reference: a stream's capture is an exact mean, slow drift is followed while
// untouched and frozen while touched, and the number of frames it stands for follows its noise.
#include "emit/frame/reference.hpp"

#include <cmath>
#include <vector>

#include <gtest/gtest.h>

#include "emit/core/errors.hpp"

namespace emit {
namespace {

Frame constant_frame(double volts) { return Frame::Constant(4, 4, volts); }

// The mean of 1, 2, 3, 4 V is 2.5 V (sums of four small integers are exact in doubles); it
// stands for the four frames.
TEST(ReferenceTracker, CaptureIsTheMeanOfTheFirstFrames) {
  ReferenceOptions options;
  options.capture_frames = 4;
  ReferenceTracker tracker(options);
  EXPECT_TRUE(tracker.capturing());
  EXPECT_FALSE(tracker.ready());
  for (int k = 1; k <= 3; ++k) EXPECT_FALSE(tracker.capture(constant_frame(k)));
  EXPECT_TRUE(tracker.capture(constant_frame(4)));
  EXPECT_FALSE(tracker.capturing());
  EXPECT_EQ(tracker.captures(), 1u);
  EXPECT_EQ(tracker.reference().frame, constant_frame(2.5));
  EXPECT_EQ(tracker.reference().frames, 4.0);
}

// A board's dropped reading (NaN) is left out of its reading's mean: (1 + 3 + 4)/3 there, 2.5 V
// elsewhere; a reading no frame held stays NaN (masked in every frame), and a NaN in a followed
// frame leaves its reading's reference as it was.
TEST(ReferenceTracker, AReadingNotFiniteIsLeftOutOfItsMean) {
  std::vector<Frame> frames = {constant_frame(1), constant_frame(2), constant_frame(3), constant_frame(4)};
  frames[1](0, 1) = std::nan("");
  for (Frame& f : frames) f(2, 3) = std::nan("");
  const Reference reference = average_reference(frames);
  EXPECT_EQ(reference.frames, 4.0);
  EXPECT_DOUBLE_EQ(reference.frame(0, 1), 8.0 / 3);
  EXPECT_EQ(reference.frame(1, 1), 2.5);
  EXPECT_TRUE(std::isnan(reference.frame(2, 3)));

  ReferenceOptions options;
  options.capture_frames = 1;
  options.drift_rate = 0.5;
  ReferenceTracker tracker(options);
  tracker.capture(constant_frame(1.0));
  Frame glitched = constant_frame(3.0);
  glitched(1, 2) = std::nan("");
  EXPECT_TRUE(tracker.follow(glitched, false));
  EXPECT_EQ(tracker.reference().frame(1, 2), 1.0);
  EXPECT_EQ(tracker.reference().frame(2, 1), 2.0);
}

// V_ref ← V_ref + r (V − V_ref): after n untouched frames at V the gap is (1 − r)^n of the start's.
TEST(ReferenceTracker, FollowsDriftWhileUntouched) {
  ReferenceOptions options;
  options.capture_frames = 1;
  options.drift_rate = 0.1;
  ReferenceTracker tracker(options);
  tracker.capture(constant_frame(1.0));
  for (int n = 0; n < 10; ++n) EXPECT_TRUE(tracker.follow(constant_frame(2.0), false));
  const double expected = 2.0 - std::pow(0.9, 10);                // gap of 1 V shrunk by 0.9 ten times
  EXPECT_NEAR(tracker.reference().frame(1, 2), expected, 1e-14);  // ten multiply-adds: a few ulps
}

// The exponential average's noise: from one frame's σ², each untouched frame makes the variance
// (1 − r)² v + r², so after k frames v_k = (1 − r)^2k + r² (1 − (1 − r)^2k) / (1 − (1 − r)²), and
// the reference stands for 1/v_k frames: 1, then more, toward (2 − r)/r (199 at r = 0.01).
TEST(ReferenceTracker, ItsFrameCountFollowsTheDriftAveragesNoise) {
  ReferenceOptions options;
  options.capture_frames = 1;
  options.drift_rate = 0.01;
  ReferenceTracker tracker(options);
  tracker.capture(constant_frame(1.0));
  EXPECT_EQ(tracker.reference().frames, 1.0);
  const double r = options.drift_rate, q = (1 - r) * (1 - r);
  for (int k = 1; k <= 2000; ++k) {
    tracker.follow(constant_frame(1.0), false);
    const double qk = std::pow(q, k), v = qk + r * r * (1 - qk) / (1 - q);
    if (k % 100 == 0) EXPECT_NEAR(tracker.reference().frames, 1 / v, 1e-9 / v) << k;  // a few ulps a step
  }
  EXPECT_NEAR(tracker.reference().frames, (2 - r) / r, 1e-3);  // (1 - r)^4000 = 3e-18 of the way left
  tracker.follow(constant_frame(1.0), true);
  EXPECT_NEAR(tracker.reference().frames, (2 - r) / r, 1e-3) << "a touched frame changes nothing";
}

// A capture's frames are averaged robustly, as a reference file's are: a frame that is far off
// the others (a touch during the capture) is left out, and the count says so.
TEST(ReferenceTracker, ACaptureLeavesOutAFrameFarOffTheOthers) {
  ReferenceOptions options;
  options.capture_frames = 5;
  ReferenceTracker tracker(options);
  for (double v : {1.0, 1.001, 0.999, 3.0, 1.0}) tracker.capture(constant_frame(v));
  EXPECT_EQ(tracker.reference().frames, 4.0);
  EXPECT_NEAR(tracker.reference().frame(0, 0), 1.0, 1e-12);
}

TEST(ReferenceTracker, FrozenWhileTouched) {
  ReferenceOptions options;
  options.capture_frames = 2;
  ReferenceTracker tracker(options);
  tracker.capture(constant_frame(1.0));
  tracker.capture(constant_frame(1.0));
  for (int n = 0; n < 100; ++n) EXPECT_FALSE(tracker.follow(constant_frame(3.0), true));
  EXPECT_EQ(tracker.reference().frame, constant_frame(1.0));
}

TEST(ReferenceTracker, RecaptureReplacesTheReference) {
  ReferenceOptions options;
  options.capture_frames = 2;
  ReferenceTracker tracker(options);
  tracker.capture(constant_frame(1.0));
  tracker.capture(constant_frame(1.0));
  tracker.recapture();
  EXPECT_TRUE(tracker.capturing());
  EXPECT_TRUE(tracker.ready());  // the old reference stays until the new one is complete
  tracker.capture(constant_frame(5.0));
  EXPECT_EQ(tracker.reference().frame, constant_frame(1.0));
  tracker.capture(constant_frame(7.0));
  EXPECT_EQ(tracker.reference().frame, constant_frame(6.0));
  EXPECT_EQ(tracker.captures(), 2u);
}

TEST(ReferenceTracker, RejectsBadOptionsAndSizes) {
  EXPECT_THROW(ReferenceTracker(ReferenceOptions{0, 0.01}), InvalidInput);
  EXPECT_THROW(ReferenceTracker(ReferenceOptions{1, 1.5}), InvalidInput);
  ReferenceTracker tracker(ReferenceOptions{1, 0.01});
  EXPECT_THROW(tracker.follow(constant_frame(1), false), InvalidInput);  // nothing captured yet
  tracker.capture(constant_frame(1));
  EXPECT_THROW(tracker.follow(Frame::Zero(3, 3), false), InvalidInput);
}

}  // namespace
}  // namespace emit
