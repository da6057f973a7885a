#pragma once
/// \file calibration.hpp
/// Calibration from presses of known force (paper §2.4, §3.2): fit a1, a2, a3 of eq. 8 so the
/// reported contact pressure matches the truth, and α, γ of eq. 2 from resistance–pressure pairs.
/// Both by nonlinear least squares (Ceres, Levenberg–Marquardt, automatic derivatives).
#include <vector>

#include "emit/reconstruct/pressure.hpp"
#include "emit/reconstruct/reconstructor.hpp"

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
double predicted_pressure(const PressureCalibration& calibration, const PressureSample& sample);

struct PressureFit {
  PressureCalibration calibration;
  std::vector<double> residuals_N_per_mm2;  ///< predicted − true, per sample
  double rms_N_per_mm2 = 0, max_abs_N_per_mm2 = 0;
};

/// Fit a1, a2, a3 to the samples (at least 3, with at least 2 distinct pressures).
/// The base a1/δφ + a2 is kept positive on every sample's potentials by fitting
/// (a1 ≥ 0, b > 0, a3) with a1/δφ + a2 = a1·(1/δφ − 1/δφ_max) + b. \throw InvalidInput, SolverError.
PressureFit fit_pressure_calibration(const std::vector<PressureSample>& samples);

struct ContactLawFit {
  double alpha = 0, gamma = 0;
  double rms_relative = 0;  ///< RMS of (R_fit − R)/R
};

/// Fit R = α P^γ (eq. 2) to pairs by least squares on relative residuals (the pairs span decades).
/// \throw InvalidInput for fewer than 2 pairs or non-positive values.
ContactLawFit fit_contact_law(const std::vector<double>& pressure_N_per_mm2, const std::vector<double>& resistance_ohm);

/// Contact fitting's calibration: eq. 2 as the fit sees it. Each single-press frame is
/// reconstructed (`reconstructor` must use a fitter and hold the reference), and α, γ are fitted
/// to the true pressure against 1/g of the strongest fitted contact.
struct FittedLawCalibration {
  ContactLaw law;
  double rms_N_per_mm2 = 0, max_abs_N_per_mm2 = 0;  ///< the law's pressure − true, over the presses
  std::size_t presses = 0;                           ///< frames that gave a contact
};
/// \param true_pressure_N_per_mm2  one per frame. \throw InvalidInput as fit_contact_law.
FittedLawCalibration calibrate_fitted_contact_law(Reconstructor& reconstructor, const std::vector<Frame>& frames,
                                                  const std::vector<double>& true_pressure_N_per_mm2,
                                                  const ContactLaw& nominal);

}  // namespace emit
