// The realistic sheet (twin/realistic_sheet.hpp): what it draws lies in the ranges asked, a seed
// is one sheet, zero sizes give the nominal twin, and its frames depart from the nominal ones.
#include "emit/twin/realistic_sheet.hpp"

#include <cmath>
#include <cstdio>

#include <gtest/gtest.h>

#include "emit/core/errors.hpp"
#include "emit/sensor/sensor_json.hpp"
#include "test_support.hpp"

namespace emit {
namespace {

Sensor square30() { return load_sensor(test::source_path("examples/sensors/square30.json")); }

TwinOptions coarse_exact_twin() {
  TwinOptions options;
  options.adc = false;
  options.mesh = MeshOptions{};
  options.mesh->element_size_mm = 1.5;
  return options;
}

TEST(RealisticSheet, DrawsWithinTheRangesAsked) {
  const Sensor nominal = square30();
  RealisticSheetOptions options;
  options.seed = 11;
  const RealisticSheet sheet = make_realistic_sheet(nominal, options, coarse_exact_twin());
  EXPECT_GE(sheet.sheet_scale, 0.7);
  EXPECT_LE(sheet.sheet_scale, 1.3);
  EXPECT_DOUBLE_EQ(sheet.twin_sensor.sheet_resistance_ohm_per_sq,
                   sheet.sheet_scale * nominal.sheet_resistance_ohm_per_sq);
  EXPECT_NEAR(std::max(sheet.field_max_factor, 1 / sheet.field_min_factor), 1.15, 1e-12);  // sheet_field_test
  EXPECT_GE(sheet.drive_voltage_V, 3.0);
  EXPECT_LE(sheet.drive_voltage_V, 3.3);
  EXPECT_EQ(sheet.twin_sensor.drive_voltage_V, sheet.drive_voltage_V);
  ASSERT_EQ(sheet.shift_mm.size(), 16u);
  ASSERT_EQ(sheet.series_ohm.size(), 16u);
  for (int e = 0; e < 16; ++e) {
    const auto i = static_cast<std::size_t>(e);
    EXPECT_LE(std::abs(sheet.shift_mm[i]), 0.5 + 1e-12) << e;
    // The shift reported is the one made: the nominal centre moved along the border by it.
    const Vector2 moved = nominal.border->point_at(nominal.electrodes[i].center_s_mm + sheet.shift_mm[i]);
    EXPECT_LT((moved - sheet.twin_sensor.electrodes[i].center_mm).norm(), 1e-9) << e;
    EXPECT_GE(sheet.series_ohm[i], 0.0);
    EXPECT_LE(sheet.series_ohm[i], 300.0);
  }
  EXPECT_EQ(sheet.twin_options.series_resistance_ohm, sheet.series_ohm);
  EXPECT_EQ(sheet.twin_options.cover_blur_mm, 1.0);
  EXPECT_TRUE(static_cast<bool>(sheet.twin_options.sheet_resistance_factor));
  EXPECT_EQ(sheet.twin_options.mesh->element_size_mm, 1.5);  // the base carried
  EXPECT_NE(sheet.description.find("electrode 15: shifted"), std::string::npos) << sheet.description;
  // A seed is one sheet.
  const RealisticSheet again = make_realistic_sheet(nominal, options, coarse_exact_twin());
  EXPECT_EQ(again.series_ohm, sheet.series_ohm);
  EXPECT_EQ(again.description, sheet.description);
  options.seed = 12;
  EXPECT_NE(make_realistic_sheet(nominal, options, coarse_exact_twin()).sheet_scale, sheet.sheet_scale);
}

// All sizes zero and the drive the nominal one: the nominal twin, frame for frame to round-off
// (the series resistances are zeros, which leave the 2×2 solves as they were).
TEST(RealisticSheet, ZeroSizesGiveTheNominalTwin) {
  const Sensor nominal = square30();
  RealisticSheetOptions options;
  options.sheet_scale = options.field = options.electrode_shift_mm = options.series_resistance_ohm = 0;
  options.blur_mm = 0;
  options.drive_voltage_low_V = options.drive_voltage_high_V = nominal.drive_voltage_V;
  const RealisticSheet sheet = make_realistic_sheet(nominal, options, coarse_exact_twin());
  Frame realistic = Twin(sheet.twin_sensor, sheet.twin_options).exact_frame({{12, 17, 4, 10}});
  const Frame plain = Twin(nominal, coarse_exact_twin()).exact_frame({{12, 17, 4, 10}});
  realistic.diagonal() = plain.diagonal();  // 0 exactly with series resistances, round-off without
  EXPECT_LE((realistic - plain).cwiseAbs().maxCoeff(), 1e-12);
}

// The realistic sheet's frame departs from the nominal twin's by more than the ADC's noise
// (1 mV) but remains the same kind of frame: within 30 % of the largest reading (the drive
// alone moves readings by up to 10 %, the sheet's scale by a few %).
TEST(RealisticSheet, FramesDepartFromTheNominal) {
  const Sensor nominal = square30();
  RealisticSheetOptions options;
  options.seed = 3;
  const RealisticSheet sheet = make_realistic_sheet(nominal, options, coarse_exact_twin());
  const Frame realistic = Twin(sheet.twin_sensor, sheet.twin_options).exact_frame({{12, 17, 4, 10}});
  const Frame plain = Twin(nominal, coarse_exact_twin()).exact_frame({{12, 17, 4, 10}});
  const double departure = (realistic - plain).cwiseAbs().maxCoeff();
  std::printf("realistic sheet seed 3: worst departure %.1f mV of %.1f mV\n", 1e3 * departure, 1e3 * plain.maxCoeff());
  EXPECT_GT(departure, 1e-3);
  EXPECT_LT(departure, 0.3 * plain.maxCoeff());
  EXPECT_EQ(realistic.diagonal().cwiseAbs().maxCoeff(), 0.0);
}

TEST(RealisticSheet, BadSizesAreRefused) {
  const Sensor nominal = square30();
  const auto error_of = [&](const RealisticSheetOptions& options) -> std::string {
    try {
      make_realistic_sheet(nominal, options);
    } catch (const InvalidInput& e) {
      return e.what();
    }
    return "no error";
  };
  RealisticSheetOptions o;
  o.sheet_scale = 1.0;
  EXPECT_EQ(error_of(o), "realistic sheet: sheet-scale must be in [0, 1)");
  o = {}, o.field = -0.1;
  EXPECT_EQ(error_of(o), "realistic sheet: field must be in [0, 1)");
  o = {}, o.series_resistance_ohm = std::nan("");
  EXPECT_EQ(error_of(o), "realistic sheet: series-ohm must be finite and >= 0");
  o = {}, o.drive_voltage_low_V = 3.4;
  EXPECT_EQ(error_of(o), "realistic sheet: the drive voltage range must satisfy 0 < low <= high");
  o = {}, o.blur_mm = -1;
  EXPECT_EQ(error_of(o), "realistic sheet: blur-mm must be finite and >= 0");
}

}  // namespace
}  // namespace emit
