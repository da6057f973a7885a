#pragma once
/// \file contact_law_calibration.hpp
/// The contact law, paper eq. 2 (R = α P^γ): fitted to resistance–pressure pairs measured on the
/// materials, and contact fitting's calibration, the law as the fit sees it, from presses of
/// known pressure. Nonlinear least squares on relative residuals (Ceres).
#include <cstddef>
#include <vector>

#include "emit/frame/contact_fitter.hpp"
#include "emit/frame/reconstructor.hpp"
#include "emit/model/reconstruction_model.hpp"

namespace emit {

struct ContactLawFit {
  double alpha = 0, gamma = 0;
  double rms_relative = 0;  ///< RMS of (R_fit − R)/R
};

/// Fit R = α P^γ (eq. 2) to pairs by least squares on relative residuals (the pairs span decades).
/// \throw InvalidInput for fewer than 2 pairs or non-positive values.
ContactLawFit fit_contact_law(const std::vector<double>& pressure_N_per_mm2, const std::vector<double>& resistance_ohm);

/// Contact fitting's calibration: eq. 2 as the fit sees it. Each single-press frame is
/// reconstructed by contact fitting (with `model`'s seeds and a fitter on `fitting`, against `reference`, one
/// frame after another as a stream), and α, γ are fitted to the true pressure against 1/g of the
/// strongest fitted contact.
struct FittedLawCalibration {
  ContactLaw law;
  double rms_N_per_mm2 = 0, max_abs_N_per_mm2 = 0;  ///< the law's pressure − true, over the presses
  std::size_t presses = 0;                          ///< frames that gave a contact
};
/// \param true_pressure_N_per_mm2  one per frame. \throw InvalidInput as fit_contact_law.
FittedLawCalibration calibrate_fitted_contact_law(const ReconstructionModel& model, const FitPrecompute& fitting,
                                                  const Reference& reference, const std::vector<Frame>& frames,
                                                  const std::vector<double>& true_pressure_N_per_mm2,
                                                  const ContactLaw& nominal, const FrameOptions& options = {});

}  // namespace emit
