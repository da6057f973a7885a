// Eq. 8 (model/pressure.hpp): P = (a1/δφ + a2)^a3 at chosen points, the base held positive, and
// the per-image map in single precision within float's rounding of the double one.
#include "emit/model/pressure.hpp"

#include <cmath>
#include <vector>

#include <gtest/gtest.h>

#include "emit/sensor/sensor_json.hpp"

namespace emit {
namespace {

// a1 = 2, a2 = −1, a3 = −2: δφ = 1 gives (2 − 1)^−2 = 1; δφ = 0.5 gives 3^−2 = 1/9.
TEST(Pressure, EquationEightAtChosenPoints) {
  const LinearCalibration c{2.0, -1.0, -2.0};
  EXPECT_DOUBLE_EQ(c.pressure_N_per_mm2(1.0), 1.0);
  EXPECT_DOUBLE_EQ(c.pressure_N_per_mm2(0.5), 1.0 / 9);
  EXPECT_EQ(c.pressure_N_per_mm2(0.0), 0.0);
  EXPECT_EQ(c.pressure_N_per_mm2(-0.1), 0.0);
  // δφ beyond the model's range (a1/δφ + a2 ≤ 0, here δφ ≥ 2) reads as the largest pressure it
  // can express, (1e-9)^−2.
  EXPECT_DOUBLE_EQ(c.pressure_N_per_mm2(4.0), 1e18);
}

// From eqs. 1–2 with R0/α = 1: a1 = E, a2 = −1, a3 = 1/γ.
TEST(Pressure, UncalibratedFollowsTheSensor) {
  const Sensor sensor = default_sensor();
  const LinearCalibration c = LinearCalibration::uncalibrated(sensor);
  EXPECT_EQ(c.a1, sensor.drive_voltage_V);
  EXPECT_EQ(c.a2, -1.0);
  EXPECT_EQ(c.a3, 1.0 / sensor.contact.gamma);
}

// The map selects δφ ≥ the threshold and agrees with the double-precision formula to float's
// rounding (a few 1e-7 relative, the header's figure); a threshold ≤ 0 selects nothing.
TEST(Pressure, MapSelectsAboveTheThresholdInSinglePrecision) {
  const LinearCalibration c{3.3, -1.0, -1.0 / 1.2};
  Vector dphi(5);
  dphi << 0.1, 0.5, 1.0, 0.29, 0.3;
  Vector pressure;
  std::vector<std::uint8_t> selected;
  c.pressure_map(dphi, 0.3, pressure, selected);
  EXPECT_EQ(selected, (std::vector<std::uint8_t>{0, 1, 1, 0, 1}));
  for (Index k = 0; k < dphi.size(); ++k) {
    const double expected = selected[static_cast<std::size_t>(k)] ? c.pressure_N_per_mm2(dphi[k]) : 0.0;
    EXPECT_NEAR(pressure[k], expected, 1e-6 * expected) << k;
  }
  c.pressure_map(dphi, 0.0, pressure, selected);
  EXPECT_EQ(selected, (std::vector<std::uint8_t>(5, 0)));
  EXPECT_EQ(pressure.cwiseAbs().maxCoeff(), 0.0);
}

}  // namespace
}  // namespace emit
