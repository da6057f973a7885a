#pragma once
/// \file pressure.hpp
/// Potential → pressure, paper eq. 8: P_k = (a1/δφ_k + a2)^a3. From eqs. 1–2, a1 = E·R0/α,
/// a2 = −R0/α, a3 = 1/γ; `emit calibrate` fits them from presses of known force.
#include <cstdint>
#include <optional>
#include <vector>

#include "emit/fit/sheet_correction.hpp"
#include "emit/sensor/sensor.hpp"
#include "emit/types.hpp"

namespace emit {

struct PressureCalibration {
  double a1 = 3.3, a2 = -1.0, a3 = -1.0 / 1.2;
  bool calibrated = false;
  /// For contact fitting instead of eq. 8: the contact law (eq. 2) as the fit sees it, fitted
  /// from presses of known pressure (the fitted disc's conductance against the true pressure).
  std::optional<ContactLaw> fitted_contact_law;
  /// For contact fitting: the sheet's resistance as the presses showed it (sheet_calibration.hpp).
  std::optional<SheetCorrection> sheet_correction;
  /// For contact fitting: the calibration presses' indenter radius [mm] (0: unknown). The frame
  /// pins a contact's total conductance G = g·A, not its area; with eq. 2 that is
  /// G = A P^(−γ)/α = A^(1+γ) F^(−γ)/α, so at γ ≈ −1.2 the force follows from G almost whatever
  /// the area (F ∝ A^(1/6) at fixed G) while the pressure does not. Contacts are reported with
  /// this indenter's area, and force = pressure × that area.
  double indenter_radius_mm = 0;

  /// The uncalibrated default from the sensor: R0/α = 1, so a1 = E, a2 = −1, a3 = 1/γ. It is
  /// monotone in δφ but its scale is arbitrary until calibrated.
  static PressureCalibration uncalibrated(const Sensor& sensor);

  /// P [N/mm²] for a thresholded potential δφ [V]; 0 for δφ ≤ 0. The base a1/δφ + a2 is kept
  /// positive (δφ beyond the model's range reads as the largest pressure it can express).
  double pressure_N_per_mm2(double dphi_V) const;
  /// Eq. 8 over a whole image, for the per-frame path: selected_k = δφ_k ≥ min_dphi_V > 0, and
  /// pressure_k = pressure_N_per_mm2(δφ_k) there, 0 elsewhere. The power is taken in single
  /// precision: twice as fast, and its 1e-7 is far below any calibration's error. Allocates
  /// nothing when the outputs already have the image's size.
  void pressure_map(const Vector& dphi_V, double min_dphi_V, Vector& pressure, std::vector<std::uint8_t>& selected) const;
};

}  // namespace emit
