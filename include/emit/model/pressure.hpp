#pragma once
/// \file pressure.hpp
/// Potential → pressure, paper eq. 8: P_k = (a1/δφ_k + a2)^a3, the linear methods' calibration.
/// From eqs. 1–2, a1 = E·R0/α, a2 = −R0/α, a3 = 1/γ; `emit calibrate` fits them from presses of
/// known force (calibrate/pressure_calibration.hpp). The per-frame path applies it by pressure_map.
///
/// Eq. 8 is the paper's per-element pressure: the picture. A contact's force summed from it over
/// the 50 % region (Σ P_k A_k) is the image's, not the press's, since that region is the image's
/// blur; a calibration from `emit calibrate` also holds emit's force law (model/force_law.hpp),
/// which gives contacts their force from the image's integral instead.
#include <cstdint>
#include <optional>
#include <vector>

#include "emit/core/types.hpp"
#include "emit/model/force_law.hpp"
#include "emit/sensor/sensor.hpp"

namespace emit {

struct LinearCalibration {
  double a1 = 3.3, a2 = -1.0, a3 = -1.0 / 1.2;
  /// The contacts' force from the image's integral (emit's calibration). None (uncalibrated, or a
  /// file written before it): a contact's force is Σ P_k A_k over its 50 % region and its area
  /// that region's, both the image's (frame/reconstructor.hpp).
  std::optional<ImageForceLaw> force_law = std::nullopt;

  /// The uncalibrated default from the sensor: R0/α = 1, so a1 = E, a2 = −1, a3 = 1/γ. It is
  /// monotone in δφ but its scale is arbitrary until calibrated.
  static LinearCalibration uncalibrated(const Sensor& sensor);

  /// P [N/mm²] for a thresholded potential δφ [V]; 0 for δφ ≤ 0. The base a1/δφ + a2 is kept
  /// positive (δφ beyond the model's range reads as the largest pressure it can express).
  double pressure_N_per_mm2(double dphi_V) const;
  /// Eq. 8 over a whole image, for the per-frame path: selected_k = δφ_k ≥ min_dphi_V > 0, and
  /// pressure_k = pressure_N_per_mm2(δφ_k) there, 0 elsewhere. The power is taken in single
  /// precision: twice as fast, and its 1e-7 is far below any calibration's error. Allocates
  /// nothing when the outputs already have the image's size.
  void pressure_map(const Vector& dphi_V, double min_dphi_V, Vector& pressure,
                    std::vector<std::uint8_t>& selected) const;
};

}  // namespace emit
