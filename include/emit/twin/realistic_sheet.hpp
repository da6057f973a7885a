#pragma once
/// \file realistic_sheet.hpp
/// A realistic sheet: a twin that departs from the nominal sensor in every way a real one does
/// at once (docs/physics.md, "The digital twin"), drawn from a seed: its overall sheet
/// resistance, a smooth field over it, its electrodes' places along the border, each
/// electrode's series resistance (contact + multiplexer switch), the drive voltage, and the
/// elastomer cover's blur. The reconstruction keeps the nominal description.
#include <cstdint>
#include <string>
#include <vector>

#include "emit/twin/twin.hpp"

namespace emit {

struct RealisticSheetOptions {
  double sheet_scale = 0.30;           ///< overall Rs × a factor uniform in [1 − s, 1 + s]
  double field = 0.15;                 ///< smooth field: Rs × exp(f), max |f| = log(1 + field)
  double electrode_shift_mm = 0.5;     ///< each electrode moved along the border, uniform ±
  double series_resistance_ohm = 300;  ///< each electrode's series resistance, uniform in [0, this]
  double drive_voltage_low_V = 3.0;    ///< the drive, uniform in [low, high]
  double drive_voltage_high_V = 3.3;
  double blur_mm = 1.0;  ///< the cover's Gaussian blur of every press (0: none)
  std::uint64_t seed = 1;
  /// \throw InvalidInput (one line naming the option) for a size out of range: sheet_scale in
  /// [0, 1), field in [0, 1), shift >= 0, series >= 0, 0 < low <= high drive, blur >= 0.
  void validate() const;
};

/// What was drawn, and the twin that simulates it.
struct RealisticSheet {
  Sensor twin_sensor;        ///< the nominal sensor with Rs scaled, electrodes shifted, the drive drawn
  TwinOptions twin_options;  ///< the base options with the field, the series resistances, the blur
  double sheet_scale = 1;    ///< Rs(twin) / Rs(nominal), before the field
  double field_min_factor = 1, field_max_factor = 1;  ///< the field's range over the sheet
  std::vector<double> shift_mm;                       ///< per electrode, along the border (counter-clockwise +)
  std::vector<double> series_ohm;                     ///< per electrode
  double drive_voltage_V = 0;
  double blur_mm = 0;
  std::string description;  ///< the above, for people: one fact a line
};

/// The realistic twin of `nominal` (which needs an analytic border: rectangle, circle, polygon).
/// `base` carries the mesh seed, the noise and the ADC. \throw InvalidInput.
RealisticSheet make_realistic_sheet(const Sensor& nominal, const RealisticSheetOptions& options,
                                    const TwinOptions& base = {});

}  // namespace emit
