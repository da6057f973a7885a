// The commands of calibration by hand (issue 33) as the README shows them: the twin's scripted
// person from `emit simulate --script calibration`, and its truth.
#include <string>

#include <gtest/gtest.h>

#include "emit/io/frames_csv.hpp"
#include "emit/io/presses_csv.hpp"
#include "test_support.hpp"

namespace emit {
namespace {

// 2 finger presses and one 3 N weight at 10 frames/s: 1 s quiet, then 3 presses of 0.4-0.6 s
// with 0.3 s lifts (README, "Calibrating by hand"): 2.2 to 3.7 s, 22 to 37 frames, each press 4
// to 6 frames (the truth ends at the last pressed frame); the weight's force as given, the
// fingers' within --force-N.
TEST(CliCapture, SimulateScriptCalibrationWritesThePersonsSessionAndItsTruth) {
  const std::string dir = test::temp_folder("cli_simulate_calibration");
  const auto r = test::run_emit("simulate --sensor " + test::source_path("examples/sensors/square30.json") +
                                " --script calibration --presses 2 --weights-N 3 --force-N 4,6 --fps 10 --out " + dir +
                                "/cal.csv");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const std::size_t frames = read_frames_csv(dir + "/cal.csv", 16).size();
  EXPECT_GE(frames, 22u);
  EXPECT_LE(frames, 37u);
  const PressSequence truth = read_presses_csv(dir + "/cal_presses.csv", frames);
  ASSERT_GE(truth.size(), 10u);
  for (std::size_t f = 0; f < 10; ++f) EXPECT_TRUE(truth[f].empty()) << "frame " << f;  // the quiet second
  int pressed = 0, weight = 0;
  for (const auto& presses : truth) {
    if (presses.empty()) continue;
    ++pressed;
    const double force_N = presses[0].force_N;
    if (force_N == 3.0) ++weight;
    else EXPECT_TRUE(force_N >= 4 && force_N <= 6) << force_N;
  }
  EXPECT_GE(pressed, 12);
  EXPECT_LE(pressed, 18);
  EXPECT_GE(weight, 4);
  EXPECT_LE(weight, 6);
}

}  // namespace
}  // namespace emit
