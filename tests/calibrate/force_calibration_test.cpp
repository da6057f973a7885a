// Emit's force law fitted from presses (calibrate/force_calibration.hpp): a known law recovered
// from its own samples, a pure power law (b2 = 0) too, the scatter reported as the rms of ln
// F̂/F, and the inputs checked with one-line errors.
#include "emit/calibrate/force_calibration.hpp"

#include <cmath>
#include <vector>

#include <gtest/gtest.h>

#include "emit/core/errors.hpp"
#include "test_support.hpp"

namespace emit {
namespace {

std::vector<ForceSample> samples_of(const ImageForceLaw& law, const std::vector<double>& integrals, double radius_mm) {
  std::vector<ForceSample> samples;
  samples.reserve(integrals.size());
  for (double I : integrals) samples.push_back({I, law.force_N(I), radius_mm});
  return samples;
}

// A saturating law like the 60 mm sheet's (b3 ≈ 1/γ = −0.84, the base reaching 0 a little past
// the largest integral): noiseless samples give it back to the solver's tolerance, and F̂ = F.
TEST(ForceCalibration, RecoversASaturatingLaw) {
  ImageForceLaw truth;
  truth.b1_V_mm2 = 40, truth.b2 = -0.5, truth.b3 = -0.84;
  const std::vector<double> integrals{2, 4, 8, 12, 20, 30, 45, 60};  // b1/I + b2 from 19.5 to 0.17
  const ForceFit fit = fit_image_force_law(samples_of(truth, integrals, 5));
  EXPECT_NEAR(fit.law.b3, truth.b3, 1e-6);
  EXPECT_NEAR(fit.law.b1_V_mm2, truth.b1_V_mm2, 1e-6 * truth.b1_V_mm2);
  EXPECT_NEAR(fit.law.b2, truth.b2, 1e-6);
  EXPECT_LT(fit.mean_abs_relative_error, 1e-8);
  EXPECT_LT(fit.law.log_std, 1e-8);
  EXPECT_EQ(fit.law.indenter_radius_mm, 5);
  ASSERT_EQ(fit.relative_errors.size(), integrals.size());
}

// F = 3·I^0.9 is the law with b2 = 0 (b3 = −0.9, b1 = 3^(1/b3)); samples scattered by ±5 % in
// turn: the fit's rms of ln F̂/F (3 parameters taken) is of that size, not 0 and not larger.
TEST(ForceCalibration, PowerLawAndItsScatter) {
  std::vector<ForceSample> samples;
  for (int i = 0; i < 20; ++i) {
    const double I = 1.0 + i, scatter = i % 2 == 0 ? 1.05 : 1 / 1.05;
    samples.push_back({I, 3 * std::pow(I, 0.9) * scatter, 4 + 0.1 * (i % 3)});
  }
  const ForceFit fit = fit_image_force_law(samples);
  EXPECT_NEAR(fit.law.b3, -0.9, 0.05);
  EXPECT_GT(fit.law.log_std, 0.8 * std::log(1.05));
  EXPECT_LT(fit.law.log_std, 1.2 * std::log(1.05));
  EXPECT_NEAR(fit.law.indenter_radius_mm, 4.1, 0.01);  // the presses' mean radius
}

TEST(ForceCalibration, InputsCheckedWithOneLineErrors) {
  EXPECT_EQ(test::error_of([] {
              fit_image_force_law({{1, 1, 5}, {2, 2, 5}, {3, 3, 5}});
            }),
            "force calibration needs at least 4 presses with a contact, got 3");
  EXPECT_EQ(test::error_of([] {
              fit_image_force_law({{1, 1, 5}, {2, 2, 5}, {0, 3, 5}, {4, 4, 5}});
            }),
            "force calibration press 2: its image's integral is not positive");
  EXPECT_EQ(test::error_of([] {
              fit_image_force_law({{1, 1, 5}, {2, 0, 5}, {3, 3, 5}, {4, 4, 5}});
            }),
            "force calibration press 1 has no force");
  EXPECT_EQ(test::error_of([] {
              fit_image_force_law({{1, 2, 5}, {2, 2, 5}, {3, 2, 5}, {4, 2, 5}});
            }),
            "force calibration needs presses of different forces");
}

}  // namespace
}  // namespace emit
