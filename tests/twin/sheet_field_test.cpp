// The smooth random sheet-resistance field (twin/sheet_field.hpp): its range, its seed, and the
// twin's plumbing of a per-point factor.
#include "emit/twin/sheet_field.hpp"

#include <cmath>

#include <gtest/gtest.h>

#include "emit/core/errors.hpp"
#include "emit/sensor/sensor_json.hpp"
#include "emit/twin/twin.hpp"
#include "test_support.hpp"

namespace emit {
namespace {

// Normalised so that max |f| = log(1.15) on the sampling grid, and the range is sampled on that
// grid: one end is exactly 1.15 or 1/1.15 (to round-off).
TEST(SheetField, RangeIsTheAmplitude) {
  const Sensor sensor = default_sensor();
  for (std::uint64_t seed : {1u, 2u, 3u}) {
    const SheetField field(*sensor.border, 0.15, seed);
    EXPECT_NEAR(std::max(field.max_factor(), 1 / field.min_factor()), 1.15, 1e-12) << seed;
    EXPECT_GE(field.min_factor(), 1 / 1.15 - 1e-12);
    EXPECT_LE(field.max_factor(), 1.15 + 1e-12);
    // Smooth: wavelengths of 30 mm or more on the 60 mm sheet, so 1 mm changes the log-factor by
    // a small share of its range 2·log 1.15 = 0.28 (at most 2π/30 per mm of each mode's weight).
    EXPECT_LT(std::abs(std::log(field.factor({20, 20})) - std::log(field.factor({21, 20}))), 0.1) << seed;
  }
  const SheetField a(*sensor.border, 0.15, 4), b(*sensor.border, 0.15, 4), c(*sensor.border, 0.15, 5);
  EXPECT_EQ(a.factor({17, 41}), b.factor({17, 41}));
  EXPECT_NE(a.factor({17, 41}), c.factor({17, 41}));
  EXPECT_EQ(SheetField(*sensor.border, 0, 4).factor({17, 41}), 1.0);
  EXPECT_THROW(SheetField(*sensor.border, 1.5, 4), InvalidInput);
}

// A factor of 2 everywhere is a sheet of twice the resistance: the same frame to round-off.
TEST(SheetField, TwinTakesAPerPointFactor) {
  Sensor sensor = load_sensor(test::source_path("examples/sensors/square30.json"));
  TwinOptions options;
  options.adc = false;
  options.mesh = MeshOptions{};
  options.mesh->element_size_mm = 2.0;
  options.sheet_resistance_factor = [](const Vector2&) { return 2.0; };
  const Frame by_factor = Twin(sensor, options).exact_frame({{12, 14, 4, 10}});
  options.sheet_resistance_factor = nullptr;
  sensor.sheet_resistance_ohm_per_sq *= 2;
  const Frame by_sheet = Twin(sensor, options).exact_frame({{12, 14, 4, 10}});
  EXPECT_LE((by_factor - by_sheet).cwiseAbs().maxCoeff(), 1e-9 * 3.3);  // solve round-off
  options.sheet_resistance_factor = [](const Vector2&) { return -1.0; };
  EXPECT_THROW(Twin(sensor, options), InvalidInput);
}

}  // namespace
}  // namespace emit
