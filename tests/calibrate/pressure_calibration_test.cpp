// Eq. 8's calibration: Levenberg–Marquardt recovers known parameters from exact data.
#include "emit/calibrate/pressure_calibration.hpp"

#include <cmath>
#include <random>

#include <gtest/gtest.h>

#include "emit/core/errors.hpp"

namespace emit {
namespace {

// Samples generated from known a1, a2, a3: the fit must reproduce every pressure to the
// solver's tolerance (exact data, an identifiable model).
TEST(PressureCalibration, RecoversPressuresFromExactSamples) {
  LinearCalibration truth;
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

TEST(PressureCalibration, RefusesTooFewOrIdenticalPresses) {
  PressureSample s{{0.1, 0.2}, {1.0, 1.0}, 0.1};
  EXPECT_THROW(fit_pressure_calibration({s, s}), InvalidInput);
  EXPECT_THROW(fit_pressure_calibration({s, s, s}), InvalidInput);  // one pressure only
}

}  // namespace
}  // namespace emit
