// The realistic round's options (eval/realistic_evaluation.hpp): refused up front, naming what is
// wrong, before a twin is meshed. The round itself runs end to end in
// tests/cli/cli_test.cpp (Cli.EvalRealisticRunsTheRoundAgainstTheTargets).
#include "emit/eval/realistic_evaluation.hpp"

#include <string>

#include <gtest/gtest.h>

#include "emit/core/errors.hpp"
#include "emit/sensor/sensor_json.hpp"

namespace emit {
namespace {

std::string message_of(const RealisticEvalOptions& options) {
  try {
    options.validate();
  } catch (const InvalidInput& e) {
    return e.what();
  }
  return "";
}

TEST(RealisticEvaluation, DefaultsAreTheReadmesRound) {
  const RealisticEvalOptions options;
  EXPECT_EQ(options.sheet.seed, 3u);
  EXPECT_EQ(options.mesh_seed, 3);
  EXPECT_EQ(options.seed, 11u);  // the README's --seed 11, 12, 13
  EXPECT_EQ(options.counts.reference_frames, 10);
  EXPECT_EQ(options.counts.calibration_presses, 40);
  EXPECT_EQ(options.counts.test_presses, 60);
  EXPECT_EQ(options.counts.calibration_iterations, 0);  // emit calibrate's own
  EXPECT_EQ(message_of(options), "");
  RealisticEvalOptions quick;
  quick.counts = quick_realistic_counts();
  EXPECT_EQ(message_of(quick), "");
  EXPECT_LT(quick.counts.test_presses, options.counts.test_presses);
}

TEST(RealisticEvaluation, BadOptionsAreNamed) {
  RealisticEvalOptions options;
  options.counts.calibration_presses = 7;
  EXPECT_EQ(message_of(options), "realistic evaluation: calibration_presses must be 8 or more, got 7");
  options = {};
  options.counts.multi_press_frames = 0;
  EXPECT_EQ(message_of(options), "realistic evaluation: multi_press_frames must be 1 or more, got 0");
  options = {};
  options.counts.calibration_iterations = -1;
  EXPECT_EQ(message_of(options), "realistic evaluation: calibration_iterations must be 0 or more, got -1");
  options = {};
  options.unplaced_known_forces = 1;  // the contact law needs two forces
  EXPECT_EQ(message_of(options),
            "realistic evaluation: unplaced_known_forces must be 0 or 2 to calibration_presses (40), got 1");
  options = {};
  options.sheet.field = 1.5;
  EXPECT_NE(message_of(options), "");  // the realistic sheet's own check
}

// Refused before any work: the call returns at once.
TEST(RealisticEvaluation, RefusesBadOptionsBeforeMeshing) {
  RealisticEvalOptions options;
  options.counts.test_presses = 0;
  EvalCase sheet;
  sheet.sensor = default_sensor();
  EXPECT_THROW(evaluate_realistic_sheet(sheet, options), InvalidInput);
}

}  // namespace
}  // namespace emit
