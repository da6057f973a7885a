// The twin as a live source (twin/sim_source.hpp), on a coarse 30 mm sheet: the random script's
// presses, held for a block of frames then lifted, on the sheet; a paced source that is not read
// drops its oldest frames; descriptions say what runs. (The figure-eight and the fixed press are
// in tests/live/live_loop_test.cpp.)
#include "emit/twin/sim_source.hpp"

#include <thread>

#include <gtest/gtest.h>

#include "emit/core/errors.hpp"
#include "emit/sensor/press_outline.hpp"
#include "emit/sensor/sensor_json.hpp"
#include "test_support.hpp"

namespace emit {
namespace {

Sensor coarse_sensor() {
  Sensor sensor = load_sensor(test::source_path("examples/sensors/square30.json"));
  sensor.mesh.element_size_mm = 2.0;  // the twin at 1 mm: quick
  return sensor;
}

// Unpaced, the script keeps its 50 frames/s clock: a press for 0.6 s (30 frames), lifted for
// 0.2 s (10), after the 15 untouched frames. Each block's press is one press, at least its
// radius + 3 mm from the border, with a force in [2, 8] N.
TEST(SimSource, RandomScriptHoldsEachPressForABlock) {
  const Sensor sensor = coarse_sensor();
  SourceOptions options;
  options.frames_per_s = 0;
  const SimSource source(sensor, parse_sim_script("sim:random"), options);
  EXPECT_EQ(source.description(), "sim: presses at random places on 30 mm, as fast as the twin goes, ADC noise on");
  for (std::uint64_t s = 0; s < 15; ++s) EXPECT_TRUE(source.presses_of(s).empty()) << s;
  // A block starts at frame 15 + 40 b; its first frame sits on the boundary of 0.8 s in doubles,
  // so the frames checked are one inside it: 1 and 28 pressed, 31 to 39 lifted.
  for (int block = 0; block < 3; ++block) {
    const std::uint64_t first = 15 + 40 * static_cast<std::uint64_t>(block);
    const auto press = source.presses_of(first + 1);
    ASSERT_EQ(press.size(), 1u) << block;
    EXPECT_GE(sensor.border->distance_to_border_mm({press[0].x_mm, press[0].y_mm}), 5.0 + 3.0);
    EXPECT_GE(press[0].force_N, 2.0);
    EXPECT_LE(press[0].force_N, 8.0);
    const auto last = source.presses_of(first + 28);
    ASSERT_EQ(last.size(), 1u);
    EXPECT_EQ(last[0].x_mm, press[0].x_mm);
    EXPECT_EQ(last[0].force_N, press[0].force_N);
    for (std::uint64_t s = first + 31; s < first + 40; ++s) EXPECT_TRUE(source.presses_of(s).empty()) << s;
  }
  EXPECT_NE(source.presses_of(16)[0].x_mm, source.presses_of(56)[0].x_mm);  // another place each block
}

// Paced like a board, the twin's frames come whether read or not, but the untouched ones before its
// first press (the reference's frames) wait for the reader: read slowly, frames 0 to 14 all come,
// in order. After them the queue holds at most queue_limit and the rest are counted as dropped.
TEST(SimSource, PacedSourceDropsWhatIsNotRead) {
  SourceOptions options;
  options.frames_per_s = 1000;
  SimSource source(coarse_sensor(), parse_sim_script("sim:fixed:10,20,5"), options);
  // The pace it says depends on this machine (sim_pace_test.cpp): the rest of the line does not.
  EXPECT_EQ(source.description().rfind("sim: a press held at (10, 20) mm, 5 N on 30 mm, 1000 frames/s", 0), 0u)
      << source.description();
  SourceFrame frame;
  for (std::uint64_t s = 0; s < 15; ++s) {
    ASSERT_TRUE(source.next(frame, std::chrono::seconds(30)));
    EXPECT_EQ(frame.sequence, s);
    if (s == 0) std::this_thread::sleep_for(std::chrono::milliseconds(200));  // 200 frames' time
  }
  EXPECT_EQ(source.dropped(), 0u);
  // The twin makes a coarse frame in milliseconds; up to 5 s is room for far more than queue_limit.
  for (int wait = 0; wait < 500 && source.dropped() == 0; ++wait)
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
  EXPECT_GT(source.dropped(), 0u);
  ASSERT_TRUE(source.next(frame, std::chrono::seconds(1)));
  EXPECT_GT(frame.sequence, 15u) << "the oldest frames were dropped";
  EXPECT_FALSE(source.finished());
}

// sim:fixed takes any outline `simulate --press` does: a bar 12 × 3 mm at 30°, held, its area
// 36 mm² exactly (a rectangle's polygon); a bad outline is refused naming the source.
TEST(SimSource, FixedHoldsAnOutline) {
  const SimScript bar = parse_sim_script("sim:fixed:bar:15,15,12,3,30,5");
  ASSERT_EQ(bar.kind, SimScript::Kind::fixed);
  EXPECT_EQ(bar.fixed.x_mm, 15.0);
  EXPECT_EQ(bar.fixed.force_N, 5.0);
  ASSERT_EQ(bar.fixed.outline_mm.size(), 1u);
  EXPECT_NEAR(press_area_mm2(bar.fixed), 36.0, 1e-9);  // L·W, in doubles
  SourceOptions options;
  options.frames_per_s = 0;
  const SimSource source(coarse_sensor(), bar, options);
  ASSERT_EQ(source.presses_of(20).size(), 1u);
  EXPECT_EQ(source.presses_of(20)[0].outline_mm.size(), 1u);
  try {
    parse_sim_script("sim:fixed:bar:15,15,12");
    FAIL() << "no error";
  } catch (const InvalidInput& e) {
    EXPECT_EQ(std::string(e.what()).rfind("source \"sim:fixed:bar:15,15,12\": ", 0), 0u) << e.what();
  }
}

TEST(SimSource, RefusesABadPace) {
  SourceOptions options;
  options.frames_per_s = -1;
  try {
    SimSource source(coarse_sensor(), parse_sim_script("sim"), options);
    FAIL() << "no error";
  } catch (const InvalidInput& e) {
    EXPECT_STREQ(e.what(), "source: frames per second must be 0 (unpaced) or positive");
  }
}

}  // namespace
}  // namespace emit
