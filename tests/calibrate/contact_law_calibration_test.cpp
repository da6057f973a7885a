// The contact law (paper eq. 2): Levenberg–Marquardt recovers known parameters from exact data.
#include "emit/calibrate/contact_law_calibration.hpp"

#include <cmath>
#include <vector>

#include <gtest/gtest.h>

#include "emit/core/errors.hpp"

namespace emit {
namespace {

// R = α P^γ recovered from exact pairs over two decades of pressure.
TEST(ContactLawCalibration, ContactLawFromResistancePairs) {
  std::vector<double> P, R;
  double p = 0.005;
  for (int k = 0; k < 19; ++k, p *= 1.3) {  // 0.005 to 0.57: 19 points (an integer counts the loop)
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
