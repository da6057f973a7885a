// Calibration: Levenberg–Marquardt recovers known parameters from exact data.
#include "emit/reconstruct/calibration.hpp"

#include <cmath>
#include <random>

#include <gtest/gtest.h>

#include "emit/errors.hpp"

namespace emit {
namespace {

// Samples generated from known a1, a2, a3: the fit must reproduce every pressure to the
// solver's tolerance (exact data, an identifiable model).
TEST(Calibration, RecoversPressuresFromExactSamples) {
  PressureCalibration truth;
  truth.a1 = 0.8, truth.a2 = 0.5, truth.a3 = -0.9;
  std::mt19937_64 rng(3);
  std::uniform_real_distribution<double> dphi(0.05, 0.6), area(0.3, 0.7);
  std::vector<PressureSample> samples;
  for (int i = 0; i < 30; ++i) {
    PressureSample s;
    const int elements = 20 + i;
    const double scale = 0.3 + 0.05 * i;  // presses of different strength
    for (int k = 0; k < elements; ++k) {
      s.dphi_V.push_back(scale * dphi(rng));
      s.area_mm2.push_back(area(rng));
    }
    s.true_pressure_N_per_mm2 = predicted_pressure(truth, s);
    samples.push_back(s);
  }
  const PressureFit fit = fit_pressure_calibration(samples);
  EXPECT_LE(fit.max_abs_N_per_mm2, 1e-6 * 0.5);  // far below 1 ppm of a 0.5 N/mm² full scale
  EXPECT_NEAR(fit.calibration.a3, truth.a3, 1e-3);
}

TEST(Calibration, RefusesTooFewOrIdenticalPresses) {
  PressureSample s{{0.1, 0.2}, {1.0, 1.0}, 0.1};
  EXPECT_THROW(fit_pressure_calibration({s, s}), InvalidInput);
  EXPECT_THROW(fit_pressure_calibration({s, s, s}), InvalidInput);  // one pressure only
}

// R = α P^γ recovered from exact pairs over two decades of pressure.
TEST(Calibration, ContactLawFromResistancePairs) {
  std::vector<double> P, R;
  for (double p = 0.005; p < 0.6; p *= 1.3) {
    P.push_back(p);
    R.push_back(2.0e5 * std::pow(p, -1.2));
  }
  const ContactLawFit fit = fit_contact_law(P, R);
  EXPECT_NEAR(fit.alpha / 2.0e5, 1.0, 1e-9);
  EXPECT_NEAR(fit.gamma, -1.2, 1e-9);
  EXPECT_LE(fit.rms_relative, 1e-9);
  EXPECT_THROW(fit_contact_law({0.1}, {1.0}), InvalidInput);
  EXPECT_THROW(fit_contact_law({0.1, -0.2}, {1.0, 2.0}), InvalidInput);
}

}  // namespace
}  // namespace emit
