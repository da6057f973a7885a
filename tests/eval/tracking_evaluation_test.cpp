// Touches over time on the twin (a mesh of another seed than the reconstruction's), with contact
// fitting as emit live runs it: two fingers crossing keep their ids, each press gives one down and
// one up; a 5 N press held still jitters at most 0.05 mm once filtered; a step is followed within a
// frame. A few crossings here (a twin frame costs ~40 ms); `emit eval --tracking` runs 200.
#include "emit/eval/tracking_evaluation.hpp"

#include <cstdio>

#include <gtest/gtest.h>

#include "emit/sensor/sensor_json.hpp"

namespace emit {
namespace {

TEST(TrackingEvaluation, CrossingFingersKeepTheirIdsAndAStillPressHoldsStill) {
  EvalCase c;
  c.name = "60 mm";
  c.sensor = default_sensor();
  TrackingEvalOptions o;
  o.crossings = 3;
  o.min_frames = 20, o.max_frames = 24;
  o.still_frames = 40;  // 30 after the filter's settling: the jitter's rms to ±13 %
  const TrackingEvaluation e = evaluate_tracking(c, o);
  std::printf(
      "swaps %d/%d unfiltered, %d/%d filtered; broken %d, %d; jitter %.4f -> %.4f mm; fit %.1f ms, track %.2f us\n",
      e.unfiltered.swapped, e.unfiltered.trials, e.filtered.swapped, e.filtered.trials, e.unfiltered.broken,
      e.filtered.broken, e.jitter_mm, e.filtered_jitter_mm, e.reconstruct_ms_per_frame, e.track_us_per_frame);
  for (const StepLag& s : e.steps)
    std::printf("step %.1f mm: lag %d filtered, %d raw\n", s.step_mm, s.lag_frames, s.raw_lag_frames);
  // The target is no swap in 99 % of crossings (emit eval --tracking measures it over 200): at that
  // rate 3 crossings hold none with probability 0.97, so any swap here fails.
  EXPECT_EQ(e.unfiltered.swapped, 0);
  EXPECT_EQ(e.filtered.swapped, 0);
  EXPECT_EQ(e.unfiltered.right_events, e.unfiltered.trials) << "each finger one down and one up";
  EXPECT_EQ(e.filtered.right_events, e.filtered.trials);
  EXPECT_LE(e.filtered_jitter_mm, 0.05);  // the target
  EXPECT_LT(e.filtered_jitter_mm, e.jitter_mm);
  ASSERT_EQ(e.steps.size(), 2u);
  for (const StepLag& s : e.steps) {
    EXPECT_GE(s.lag_frames, 0) << "step " << s.step_mm;
    EXPECT_LE(s.lag_frames, 1) << "step " << s.step_mm;  // the target
  }
}

}  // namespace
}  // namespace emit
