#pragma once
/// \file pressure_calibration.hpp
/// The linear methods' calibration from presses of known force (paper §2.4, §3.2): a1, a2, a3 of
/// eq. 8 fitted so the reported contact pressure matches the truth, by nonlinear least squares
/// (Ceres, Levenberg–Marquardt, automatic derivatives).
#include <vector>

#include "emit/frame/reconstructor.hpp"
#include "emit/model/pressure.hpp"

namespace emit {

/// One calibration press: the thresholded elements' potentials and areas, and the true pressure.
struct PressureSample {
  std::vector<double> dphi_V, area_mm2;
  double true_pressure_N_per_mm2 = 0;
};

/// The sample of the reconstructor's current image: every element above the threshold.
PressureSample pressure_sample(const Reconstructor& reconstructor, double threshold_fraction,
                               double true_pressure_N_per_mm2);

/// The contact pressure the pipeline reports for a sample: Σ A_k P_k / Σ A_k with eq. 8.
double predicted_pressure(const LinearCalibration& calibration, const PressureSample& sample);

struct PressureFit {
  LinearCalibration calibration;
  std::vector<double> residuals_N_per_mm2;  ///< predicted − true, per sample
  double rms_N_per_mm2 = 0, max_abs_N_per_mm2 = 0;
};

/// Fit a1, a2, a3 to the samples (at least 3, with at least 2 distinct pressures).
/// The base a1/δφ + a2 is kept positive on every sample's potentials by fitting
/// (a1 ≥ 0, b > 0, a3) with a1/δφ + a2 = a1·(1/δφ − 1/δφ_max) + b. \throw InvalidInput, SolverError.
PressureFit fit_pressure_calibration(const std::vector<PressureSample>& samples);

}  // namespace emit
