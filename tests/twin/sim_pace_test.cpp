// The simulator's pace: it times a few twin frames at start and, asked for a rate it cannot keep,
// runs at the one it can (80 % of its thread's time, whole frames/s) and says so; asked for one it
// can keep, it keeps it. Its frames' board times and script follow the rate it runs at.
#include <gtest/gtest.h>

#include "emit/sensor/sensor_json.hpp"
#include "emit/twin/sim_source.hpp"

namespace emit {
namespace {

TEST(SimPace, SaysWhenItCannotKeepTheAskedRateAndRunsAtOneItCan) {
  SourceOptions options;
  options.frames_per_s = 1e5;  // 10 µs a frame: no twin frame is that fast
  options.untouched_frames = 0;
  SimSource source(default_sensor(), SimScript{}, options);
  ASSERT_GT(source.measured_frame_s(), 0);
  EXPECT_LT(source.frames_per_s(), options.frames_per_s);
  // 80 % of the thread's time at the measured cost, rounded down to whole frames/s.
  EXPECT_LE(source.frames_per_s(), 0.8 / source.measured_frame_s());
  EXPECT_GE(source.frames_per_s(), std::max(1.0, 0.8 / source.measured_frame_s() - 1));
  EXPECT_NE(source.description().find("asked, but a twin frame takes"), std::string::npos) << source.description();
  // Board times follow the rate it runs at.
  SourceFrame first, second;
  ASSERT_TRUE(source.next(first, std::chrono::milliseconds(5000)));
  ASSERT_TRUE(source.next(second, std::chrono::milliseconds(5000)));
  EXPECT_NEAR(second.board_time_s - first.board_time_s, 1 / source.frames_per_s(), 1e-9);
  EXPECT_GT(source.frame_cost_s(), 0);
}

TEST(SimPace, KeepsARateItCan) {
  SourceOptions options;
  options.frames_per_s = 1;  // a second a frame: any twin keeps it
  const SimSource source(default_sensor(), SimScript{}, options);
  EXPECT_EQ(source.frames_per_s(), 1);
  EXPECT_EQ(source.description().find("asked, but"), std::string::npos) << source.description();
}

}  // namespace
}  // namespace emit
