// The twin's departures from the description (twin/sensor_mismatch.hpp): electrodes moved along
// the border by at most the shift asked, the same for the same seed, and the five standard
// mismatches, each changing the one thing its name says.
#include "emit/twin/sensor_mismatch.hpp"

#include <cmath>

#include <gtest/gtest.h>

#include "emit/core/errors.hpp"
#include "emit/sensor/sensor_json.hpp"

namespace emit {
namespace {

/// The shortest distance along a closed border of length `length` between arc lengths a and b.
double along_border(double a, double b, double length) {
  const double d = std::fmod(std::abs(a - b), length);
  return std::min(d, length - d);
}

TEST(SensorMismatch, ShiftedElectrodesStayOnTheBorderWithinTheShift) {
  const Sensor nominal = default_sensor();
  const Sensor shifted = with_shifted_electrodes(nominal, 0.5, 7);
  ASSERT_EQ(shifted.electrode_count(), nominal.electrode_count());
  const double length = nominal.border->length_mm();
  double largest = 0;
  for (int e = 0; e < nominal.electrode_count(); ++e) {
    const Electrode& a = nominal.electrodes[static_cast<std::size_t>(e)];
    const Electrode& b = shifted.electrodes[static_cast<std::size_t>(e)];
    const double moved = along_border(a.center_s_mm, b.center_s_mm, length);
    EXPECT_LE(moved, 0.5 + 1e-12) << e;
    largest = std::max(largest, moved);
    EXPECT_LT(nominal.border->distance_to_border_mm(b.center_mm), 1e-9) << e;  // its centre is on the border
    EXPECT_EQ(b.width_mm, a.width_mm);
  }
  EXPECT_GT(largest, 0.0);
  // The same seed, the same sensor; another seed, another.
  EXPECT_EQ(with_shifted_electrodes(nominal, 0.5, 7).electrodes[3].center_s_mm, shifted.electrodes[3].center_s_mm);
  EXPECT_NE(with_shifted_electrodes(nominal, 0.5, 8).electrodes[3].center_s_mm, shifted.electrodes[3].center_s_mm);
}

TEST(SensorMismatch, ShiftingNeedsAnAnalyticBorder) {
  Sensor from_a_mesh = default_sensor();
  from_a_mesh.border.reset();
  try {
    with_shifted_electrodes(from_a_mesh, 0.5, 1);
    FAIL() << "no error";
  } catch (const InvalidInput& e) {
    EXPECT_STREQ(e.what(), "shifting electrodes needs an analytic border");
  }
}

TEST(SensorMismatch, StandardMismatchesChangeOneThingEach) {
  const Sensor nominal = default_sensor();
  TwinOptions base;
  base.mesh_seed = 3;
  const std::vector<Mismatch> m = standard_mismatches(nominal, base, 1);
  ASSERT_EQ(m.size(), 5u);
  for (const Mismatch& each : m) EXPECT_EQ(each.twin_options.mesh_seed, 3) << each.name;  // the base carried
  EXPECT_EQ(m[0].name, "sheet resistance +/-20 % across");
  EXPECT_EQ(m[0].twin_options.sheet_resistance_variation, 0.2);
  EXPECT_NE(m[1].twin_sensor.electrodes[0].center_s_mm, nominal.electrodes[0].center_s_mm);
  EXPECT_EQ(m[2].twin_sensor.contact.gamma, -1.0);
  EXPECT_EQ(m[2].twin_sensor.contact.alpha_ohm_mm2, 2 * nominal.contact.alpha_ohm_mm2);
  EXPECT_EQ(m[3].twin_options.driving_sheet_resistance_ohm_per_sq, 0.1 * nominal.sheet_resistance_ohm_per_sq);
  EXPECT_EQ(m[4].name, "electrode 5 disconnected");
  EXPECT_EQ(m[4].twin_options.dead_electrode, 5);
  EXPECT_EQ(m[4].twin_sensor.contact.gamma, nominal.contact.gamma);  // nothing else changed
}

}  // namespace
}  // namespace emit
