#pragma once
/// \file calibration.hpp
/// A calibration is one of two kinds, each for its kind of method (model/method.hpp): eq. 8 for
/// the linear methods (pressure.hpp), the contact law and the sheet as contact fitting sees them.
/// The types keep them apart: a linear Reconstructor takes a LinearCalibration, a fitting one a
/// FitCalibration; only a file read from disk holds either (io/calibration_json.hpp), and the
/// pipeline checks it against the method then (pipeline/pipeline.hpp).
#include <optional>
#include <string>
#include <variant>
#include <vector>

#include "emit/model/pressure.hpp"
#include "emit/model/sheet_correction.hpp"
#include "emit/sensor/sensor.hpp"

namespace emit {

/// Contact fitting's calibration, fitted from presses of known place and pressure
/// (calibrate/contact_law_calibration.hpp, calibrate/sensor_calibration.hpp).
struct FitCalibration {
  /// The contact law (paper eq. 2) as the fit sees it: the fitted disc's conductance against the
  /// true pressure.
  ContactLaw contact_law;
  /// The sheet's resistance as the presses showed it; none: the nominal sheet.
  std::optional<SheetCorrection> sheet_correction;
  /// The calibration presses' indenter radius [mm] (0: unknown). The frame pins a contact's total
  /// conductance G = g·A, not its area; with eq. 2 that is G = A P^(−γ)/α = A^(1+γ) F^(−γ)/α, so
  /// at γ ≈ −1.2 the force follows from G almost whatever the area (F ∝ A^(1/6) at fixed G) while
  /// the pressure does not. Contacts are reported with this indenter's area, and force =
  /// pressure × that area.
  double indenter_radius_mm = 0;
  /// The drive voltage [V] and each electrode's series resistance [Ω] as the presses showed them
  /// (calibrate/sensor_calibration.hpp); 0 and empty: the sensor's own.
  double drive_voltage_V = 0;
  std::vector<double> series_resistance_ohm;
  /// Each electrode's slide along the border [mm] as the presses showed it; empty: none. Contact
  /// fitting's mesh is slid by it (mesh/slide_electrodes.hpp), as the calibration fitted it.
  std::vector<double> electrode_shift_mm;
  /// The sensor it was made for: its electrode count (0: unknown) and name. A calibration of
  /// another sensor is refused (pipeline/pipeline.hpp).
  int electrode_count = 0;
  std::string sensor_name;

  /// Uncalibrated: the sensor's own contact law, the nominal sheet, the fitted disc's area.
  static FitCalibration uncalibrated(const Sensor& sensor) {
    FitCalibration c;
    c.contact_law = sensor.contact;
    return c;
  }
  /// The sensor as this calibration sees it: its contact law, drive voltage and series resistances.
  Sensor applied_to(const Sensor& sensor) const {
    Sensor s = sensor;
    s.contact = contact_law;
    if (drive_voltage_V > 0) s.drive_voltage_V = drive_voltage_V;
    if (!series_resistance_ohm.empty()) s.series_resistance_ohm = series_resistance_ohm;
    return s;
  }
};

using Calibration = std::variant<LinearCalibration, FitCalibration>;

/// "eq. 8 (linear methods)" or "contact fitting": which kind of method a calibration is for.
inline const char* calibration_kind(const Calibration& calibration) {
  return std::holds_alternative<LinearCalibration>(calibration) ? "the linear methods" : "contact fitting";
}

}  // namespace emit
