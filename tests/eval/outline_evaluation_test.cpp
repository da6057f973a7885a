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

// Coverage reads a reported σ as one of the log (σ/value): 100 ± 50 is ln-σ 0.5, so a truth of
// 60 (ln 100/60 = 0.51) is outside 1σ and inside 2σ, one of 140 (0.34) inside 1σ; nothing
// reported, or a σ of 0, covers nothing.
TEST(OutlineEvaluation, CoverageIsOnTheLogOfTheValue) {
  EXPECT_FALSE(within_sigmas(100, 50, 60, 1));
  EXPECT_TRUE(within_sigmas(100, 50, 60, 2));
  EXPECT_TRUE(within_sigmas(100, 50, 140, 1));
  EXPECT_FALSE(within_sigmas(0, 50, 60, 2));
  EXPECT_FALSE(within_sigmas(100, 0, 99, 2));
  EXPECT_TRUE(within_sigmas(100, 0, 100, 1));
}

// The summary's coverage: fractions of all frames (one without contacts outside), NaN for a
// method that reports no σ of a quantity (its table prints "-").
TEST(OutlineEvaluation, SummaryCountsCoverageOnlyWhereSigmasAreReported) {
  OutlineScore a, b, c;
  a.area_mm2 = 100, a.area_std_mm2 = 50, a.true_area_mm2 = 60;   // 2σ
  a.force_N = 10, a.true_force_N = 10;                           // no force σ
  b.area_mm2 = 100, b.area_std_mm2 = 50, b.true_area_mm2 = 100;  // 1σ
  b.force_N = 10, b.true_force_N = 10;
  c.true_area_mm2 = 50, c.true_force_N = 5;  // nothing reported
  const OutlineFamilyScore s = summarize_outline_scores("disc", {a, b, c});
  EXPECT_DOUBLE_EQ(s.area_within_1sigma, 1.0 / 3);
  EXPECT_DOUBLE_EQ(s.area_within_2sigma, 2.0 / 3);
  EXPECT_TRUE(std::isnan(s.force_within_1sigma));
  EXPECT_TRUE(std::isnan(s.force_within_2sigma));
  EXPECT_DOUBLE_EQ(s.area_ratio, (100.0 / 60 + 1 + 0) / 3);
}

}  // namespace
}  // namespace emit
