#include "emit/twin/realistic_sheet.hpp"

#include <cmath>
#include <cstdio>
#include <memory>
#include <random>

#include "emit/core/errors.hpp"
#include "emit/twin/sensor_mismatch.hpp"
#include "emit/twin/sheet_field.hpp"

namespace emit {

namespace {

/// The signed distance along a closed border from arc length a to b, in (−length/2, length/2].
double signed_along_border(double a, double b, double length) {
  double d = std::fmod(b - a, length);
  if (d > length / 2) d -= length;
  if (d <= -length / 2) d += length;
  return d;
}

std::string format_line(const char* format, double a, double b = 0, double c = 0) {
  char line[160];
  std::snprintf(line, sizeof line, format, a, b, c);
  return line;
}

}  // namespace

void RealisticSheetOptions::validate() const {
  const RealisticSheetOptions& o = *this;
  const auto check = [](bool ok, const char* message) {
    if (!ok) throw InvalidInput(message);
  };
  check(o.sheet_scale >= 0 && o.sheet_scale < 1, "realistic sheet: sheet-scale must be in [0, 1)");
  check(o.field >= 0 && o.field < 1, "realistic sheet: field must be in [0, 1)");
  check(o.electrode_shift_mm >= 0 && std::isfinite(o.electrode_shift_mm),
        "realistic sheet: shift-mm must be finite and >= 0");
  check(o.series_resistance_ohm >= 0 && std::isfinite(o.series_resistance_ohm),
        "realistic sheet: series-ohm must be finite and >= 0");
  check(o.drive_voltage_low_V > 0 && o.drive_voltage_high_V >= o.drive_voltage_low_V &&
            std::isfinite(o.drive_voltage_high_V),
        "realistic sheet: the drive voltage range must satisfy 0 < low <= high");
  check(o.blur_mm >= 0 && std::isfinite(o.blur_mm), "realistic sheet: blur-mm must be finite and >= 0");
}

RealisticSheet make_realistic_sheet(const Sensor& nominal, const RealisticSheetOptions& options,
                                    const TwinOptions& base) {
  options.validate();
  if (!nominal.border) throw InvalidInput("a realistic sheet needs an analytic border, not a mesh file");
  RealisticSheet sheet;
  // One stream of draws, in a fixed order, so a seed is one sheet; each part that draws many
  // values (the field, the shifts) gets a seed of its own from it.
  std::mt19937_64 rng(options.seed);
  const auto uniform = [&](double a, double b) {
    return a == b ? a : std::uniform_real_distribution<double>(a, b)(rng);
  };
  sheet.sheet_scale = uniform(1 - options.sheet_scale, 1 + options.sheet_scale);
  const std::uint64_t field_seed = rng(), shift_seed = rng();
  sheet.drive_voltage_V = uniform(options.drive_voltage_low_V, options.drive_voltage_high_V);
  sheet.blur_mm = options.blur_mm;

  sheet.twin_sensor = options.electrode_shift_mm > 0
                          ? with_shifted_electrodes(nominal, options.electrode_shift_mm, shift_seed)
                          : nominal;
  sheet.twin_sensor.sheet_resistance_ohm_per_sq *= sheet.sheet_scale;
  sheet.twin_sensor.drive_voltage_V = sheet.drive_voltage_V;
  const int N = nominal.electrode_count();
  for (int e = 0; e < N; ++e) {
    const auto i = static_cast<std::size_t>(e);
    sheet.shift_mm.push_back(signed_along_border(nominal.electrodes[i].center_s_mm,
                                                 sheet.twin_sensor.electrodes[i].center_s_mm,
                                                 nominal.border->length_mm()));
    sheet.series_ohm.push_back(uniform(0, options.series_resistance_ohm));
  }

  sheet.twin_options = base;
  sheet.twin_options.series_resistance_ohm = sheet.series_ohm;
  sheet.twin_options.cover_blur_mm = options.blur_mm;
  if (options.field > 0) {
    const auto field = std::make_shared<const SheetField>(*nominal.border, options.field, field_seed);
    sheet.field_min_factor = field->min_factor(), sheet.field_max_factor = field->max_factor();
    sheet.twin_options.sheet_resistance_factor = [field](const Vector2& p) { return field->factor(p); };
  }

  std::string& d = sheet.description;
  d += "realistic sheet, seed " + std::to_string(options.seed) + "\n";
  d += format_line("sheet resistance: %.4f x nominal (%.1f ohm/sq)\n", sheet.sheet_scale,
                   sheet.twin_sensor.sheet_resistance_ohm_per_sq);
  d += format_line("smooth field over the sheet: x %.4f to x %.4f\n", sheet.field_min_factor, sheet.field_max_factor);
  d += format_line("drive voltage: %.4f V\n", sheet.drive_voltage_V);
  d += format_line("cover blur: %.3f mm\n", sheet.blur_mm);
  for (int e = 0; e < N; ++e) {
    const auto i = static_cast<std::size_t>(e);
    d += "electrode " + std::to_string(e) +
         format_line(": shifted %+.3f mm along the border, series %.1f ohm\n", sheet.shift_mm[i], sheet.series_ohm[i]);
  }
  return sheet;
}

}  // namespace emit
