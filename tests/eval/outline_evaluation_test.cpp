// The outline round's options and summaries (eval/outline_evaluation.hpp). The round itself runs
// end to end in tests/cli/cli_test.cpp (Cli.EvalOutlinesScoresEachMethodPerOutline).
#include "emit/eval/outline_evaluation.hpp"

#include <cmath>
#include <limits>

#include <gtest/gtest.h>

#include "emit/core/errors.hpp"
#include "emit/sensor/sensor_json.hpp"
#include "test_support.hpp"

namespace emit {
namespace {

TEST(OutlineEvaluation, DefaultsAndQuick) {
  const OutlineEvalOptions options;
  EXPECT_EQ(options.calibration_presses, 40);
  EXPECT_EQ(options.presses_per_family * static_cast<int>(outline_families().size()), 48);  // issue 31's count
  EXPECT_EQ(test::error_of([&] { options.validate(); }), "no error");
  const OutlineEvalOptions quick = quick_outline_options();
  EXPECT_EQ(test::error_of([&] { quick.validate(); }), "no error");
  EXPECT_LT(quick.presses_per_family, options.presses_per_family);
}

TEST(OutlineEvaluation, BadOptionsAreNamedBeforeAnyWork) {
  OutlineEvalOptions options;
  options.calibration_presses = 7;
  EXPECT_EQ(test::error_of([&] { options.validate(); }),
            "outline evaluation: calibration_presses must be 8 or more, got 7");
  options = {};
  options.methods.clear();
  EXPECT_EQ(test::error_of([&] { options.validate(); }), "outline evaluation: no method to evaluate");
  EvalCase dome;
  dome.sensor = test::dome_sensor();
  EXPECT_EQ(test::error_of([&] { evaluate_outlines(dome, OutlineEvalOptions{}); }),
            "outline evaluation: the sheet must be flat");
}

// Means over the frames; the centroid over those with a region, the orientation over those
// that have one to score.
TEST(OutlineEvaluation, SummaryAveragesFrames) {
  OutlineScore a, b;
  a.dice = 0.8, a.force_N = 11, a.true_force_N = 10, a.centroid_error_mm = 1, a.orientation_error_deg = 4;
  a.regions = 1, a.presses = 1;
  b.dice = 0.4, b.force_N = 0, b.true_force_N = 5, b.centroid_error_mm = std::numeric_limits<double>::quiet_NaN();
  b.orientation_error_deg = 90, b.regions = 0, b.presses = 1;
  const OutlineFamilyScore s = summarize_outline_scores("bar", {a, b});
  EXPECT_EQ(s.family, "bar");
  EXPECT_EQ(s.frames, 2);
  EXPECT_DOUBLE_EQ(s.dice, 0.6);
  EXPECT_DOUBLE_EQ(s.force_ratio, (1.1 + 0) / 2);
  EXPECT_DOUBLE_EQ(s.force_error, (0.1 + 1) / 2);
  EXPECT_DOUBLE_EQ(s.centroid_mm, 1);
  EXPECT_EQ(s.frames_without_region, 1);
  EXPECT_DOUBLE_EQ(s.orientation_deg, 47);
  EXPECT_DOUBLE_EQ(s.regions, 0.5);
  EXPECT_DOUBLE_EQ(s.right_count, 0.5);
}

}  // namespace
}  // namespace emit
