#pragma once
/// \file force_calibration.hpp
/// Emit's force law for the linear methods (model/force_law.hpp) fitted from presses of known
/// force: F = (b1/I + b2)^b3 on each press's integral of the image, by nonlinear least squares on
/// ln F (relative errors, so 2 N and 39 N presses weigh alike; Ceres, Levenberg–Marquardt,
/// automatic derivatives), as eq. 8 is fitted to pressures (calibrate/pressure_calibration.hpp).
#include <vector>

#include "emit/model/force_law.hpp"

namespace emit {

/// One calibration press: its contact's integral of the image (frame/image_forces.hpp) and its
/// true force and indenter radius.
struct ForceSample {
  double integral_V_mm2 = 0;
  double true_force_N = 0;
  double radius_mm = 0;
};

struct ForceFit {
  ImageForceLaw law;
  std::vector<double> relative_errors;  ///< F̂/F − 1, per sample
  double mean_abs_relative_error = 0;   ///< mean |F̂/F − 1| over the samples
};

/// Fit b1, b2, b3 to the samples (at least 4, with at least 2 distinct forces, every integral
/// and force positive). The base b1/I + b2 is kept positive on every sample by fitting (b1 ≥ 0,
/// c > 0, b3) with b1/I + b2 = b1·(1/I − 1/I_max) + c. law.log_std is the rms of ln(F̂/F) with
/// 3 degrees of freedom taken; law.indenter_radius_mm the samples' mean radius.
/// \throw InvalidInput naming the press, SolverError.
ForceFit fit_image_force_law(const std::vector<ForceSample>& samples);

}  // namespace emit
