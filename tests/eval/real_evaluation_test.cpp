// emit eval --real's evaluation (eval/real_evaluation.hpp) on a data set made by a known smooth
// response, so that it runs without the real data: the calibration locates held-out presses as
// cross-validation said, the curve is one point per count asked, a frame that cannot be read is
// missed, not misplaced, and frames that do not fit the sensor are refused in one line.
#include "emit/eval/real_evaluation.hpp"

#include <limits>
#include <random>
#include <vector>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "emit/sensor/sensor_json.hpp"
#include "test_support.hpp"

namespace emit {
namespace {

/// 8 electrodes on a circle of 40 mm, adjacent drive, every adjacent pair read: 64 readings.
Sensor ring_skin() {
  return parse_sensor(nlohmann::json{{"shape", {{"type", "circle"}, {"radius_mm", 40}, {"center_mm", {0, 0}}}},
                                     {"electrodes", {{"count", 8}, {"width_mm", 3}}},
                                     {"excitation", {{"drive", "adjacent"}}},
                                     {"mesh", {{"element_size_mm", 4}}}});
}

/// n presses uniform in a disc of 30 mm, each frame the reference times exp of a cubic response
/// of the place plus 1 % noise.
RealDataset cubic_skin(int n) {
  PressResponse truth;
  truth.degree = 3;
  truth.scale_mm = 30;
  std::mt19937 random(5);
  std::normal_distribution<double> normal;
  truth.coefficients = Matrix(response_basis_size(3), 64);
  for (Index i = 0; i < truth.coefficients.size(); ++i) truth.coefficients(i) = 0.01 * normal(random);
  RealDataset d;
  d.folder = "cubic";
  d.frames.resize(n, 64);
  d.references = Matrix::Constant(n, 64, 1000);
  d.per_frame_references = true;
  std::uniform_real_distribution<double> uniform(-30, 30);
  Vector basis(response_basis_size(3));
  for (int i = 0; i < n;) {
    const Vector2 p(uniform(random), uniform(random));
    if (p.norm() > 30) continue;
    truth.basis_at(p, basis);
    Vector change = truth.coefficients.transpose() * basis;
    for (Index m = 0; m < 64; ++m) change(m) += 1e-4 * normal(random);
    d.frames.row(i) = 1000 * change.array().exp().transpose();
    d.contacts.push_back({p});
    ++i;
  }
  return d;
}

TEST(RealEvaluation, LocatesHeldOutPressesAsCrossValidationSaid) {
  RealDataset data = cubic_skin(120);
  data.frames(110, 3) = 0;               // a held-out frame with a dropped sample: masked, the frame located
  data.frames.row(100).setConstant(-1);  // and one with no reading to use: missed
  RealEvalOptions options;
  options.calibration_presses = 60;
  options.test_from = 90;
  options.curve = {30, 60, 200};  // 200 is past the held-out presses: skipped
  options.fit.degrees = {2, 3};
  options.fit.shrinkages = {1.0};
  options.fit.kernel_lengths_mm = {};
  const RealEvaluation e = evaluate_real(data, ring_skin(), options);
  EXPECT_EQ(e.fit.kept.degree, 3);
  ASSERT_EQ(e.curve.size(), 2u);
  EXPECT_EQ(e.curve[0].calibration_presses, 30);
  EXPECT_EQ(e.curve[1].calibration_presses, 60);
  EXPECT_EQ(e.curve[1].held_out.mean, e.held_out.mean);
  // Normalising a change bends the cubic (a normalised polynomial is not one), which sets the
  // floor here (0.9 mm cross-validated over a 60 mm disc, not the noise's 1e-4 of ~1e-2): the
  // held-out presses are placed as cross-validation said, within a factor 2 (1.1 mm measured).
  EXPECT_LT(e.held_out.mean, 2 * e.fit.kept.cross_validated_mm);
  EXPECT_GT(e.held_out.mean, e.fit.kept.cross_validated_mm / 2);
  EXPECT_LT(e.held_out.mean, 1.5);
  EXPECT_EQ(e.held_out.count, 29);
  EXPECT_EQ(e.held_out.missed, 1);
  EXPECT_EQ(e.located.size(), 60u);  // presses 60 … 119
  EXPECT_FALSE(e.located[40].found);
  ASSERT_TRUE(e.located[50].found);
  EXPECT_EQ(e.located[50].masked, 1);
  EXPECT_LT((e.located[50].position_mm - data.contacts[110].front()).norm(), 3 * e.fit.kept.cross_validated_mm);
  EXPECT_EQ(e.survey.masked_readings, 1 + 64);
  EXPECT_EQ(e.survey.frames_with_bad, 2);
  ASSERT_TRUE(e.held_out_image);
  EXPECT_EQ(e.held_out_image->missed, 1);
  EXPECT_GT(e.held_out_centre.mean, 5 * e.held_out.mean);
  // Each press's σ, scaled on calibration presses the fit did not see (split conformal: 68 % and
  // 95 % or more of new exchangeable presses within 1σ and 2σ, in expectation).
  EXPECT_GT(e.fit.response.error_scale_mm, 0);
  EXPECT_GE(e.within_1sigma, 0.68) << e.held_out_sigma_mm << " mm mean sigma";
  EXPECT_GE(e.within_2sigma, 0.95);
}

TEST(RealEvaluation, RefusesFramesThatDoNotFitTheSensor) {
  RealDataset data = cubic_skin(40);
  RealEvalOptions options;
  options.calibration_presses = 20;
  options.curve = {};
  options.image = false;
  Sensor other = ring_skin();
  other.excitation->readings.pop_back();
  EXPECT_EQ(test::error_of([&] { evaluate_real(data, other, options); }),
            "cubic/frames.csv: 64 values a frame, the sensor's excitation reads 63");
  other.excitation.reset();
  EXPECT_EQ(test::error_of([&] { evaluate_real(data, other, options); }),
            "the sensor has no \"excitation\": emit eval --real needs a current-injection skin's protocol");
  data.contacts[3].emplace_back(1, 1);
  EXPECT_EQ(test::error_of([&] { evaluate_real(data, ring_skin(), options); }),
            "cubic/truth.csv: frame 3 has 2 presses; emit eval --real takes single presses");
  data.contacts[3].pop_back();
  options.calibration_presses = 35;
  EXPECT_EQ(test::error_of([&] { evaluate_real(data, ring_skin(), options); }),
            "--calibration-presses: must be between 20 and 32 (the presses before the held-out ones), got 35");
}

// Bad readings in the calibration presses are masked, not fatal: a dropped sample is filled from
// the model at the press's place, a press with nothing to use (a frame equal to its reference) is
// left out and listed, and a channel bad in most frames is dropped; the held-out error stays
// within 10 % of the clean data's.
TEST(RealEvaluation, CalibratesThroughBadReadings) {
  const RealDataset clean = cubic_skin(120);
  RealEvalOptions options;
  options.calibration_presses = 60;
  options.test_from = 90;
  options.curve = {};
  options.image = false;
  options.fit.degrees = {3};
  options.fit.shrinkages = {1.0};
  options.fit.kernel_lengths_mm = {};
  const RealEvaluation reference = evaluate_real(clean, ring_skin(), options);
  RealDataset data = clean;
  data.frames(5, 0) = 0;
  data.frames(7, 9) = std::numeric_limits<double>::quiet_NaN();
  data.frames.row(12) = data.references.row(12);
  for (Index i = 0; i < 70; ++i) data.frames(i, 20) = -1;  // 70 of 120: dropped for good
  const RealEvaluation e = evaluate_real(data, ring_skin(), options);
  EXPECT_EQ(e.unusable_calibration_presses, std::vector<Index>{12});
  EXPECT_EQ(e.survey.dropped(), std::vector<Index>{20});
  EXPECT_EQ(e.fit.filled_presses, 2);
  EXPECT_EQ(e.held_out.missed, 0);
  EXPECT_LT(e.held_out.mean, 1.1 * reference.held_out.mean + 0.05)
      << e.held_out.mean << " against " << reference.held_out.mean << " mm clean";
}

// A folder of too few presses for calibration and held-out presses is named, with the presses it
// holds and needs (it said "--calibration-presses: must be between 20 and 4", of an option never
// given); an explicit --test-from is held to the folder.
TEST(RealEvaluation, AFolderOfTooFewPressesSaysWhatItNeeds) {
  const RealDataset five = cubic_skin(5);
  RealEvalOptions options;
  EXPECT_EQ(test::error_of([&] { evaluate_real(five, ring_skin(), options); }),
            "cubic: 5 presses, too few: calibration takes at least 20 (2 per fold of its 10-fold cross-validation) "
            "and the held-out presses (the last fifth) 1 or more; the folder needs 24 presses or more");
  options.test_from = 3;
  EXPECT_EQ(test::error_of([&] { evaluate_real(five, ring_skin(), options); }),
            "cubic: 5 presses, too few: calibration takes at least 20 (2 per fold of its 10-fold cross-validation) "
            "and the held-out presses 1 or more; the folder needs 21 presses or more");
  const RealDataset forty = cubic_skin(40);
  options.test_from = 10;
  EXPECT_EQ(test::error_of([&] { evaluate_real(forty, ring_skin(), options); }),
            "--test-from: must be between 20, the least calibration takes (2 per fold of its 10-fold "
            "cross-validation), and 39 (cubic's presses less one), got 10");
  // 24 presses are enough: 20 to calibrate on, the last 4 held out.
  options.test_from = -1;
  options.calibration_presses = 20;
  EXPECT_NO_THROW(options.validate(24, "cubic"));
}

}  // namespace
}  // namespace emit
