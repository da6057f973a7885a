#pragma once
/// \file press_calibration.hpp
/// Calibration from presses of known place and force, for a method (`emit calibrate`): the models
/// built as the pipeline builds them, the presses reconstructed, and the method's kind of
/// calibration fitted (model/calibration.hpp). For the linear methods, eq. 8's a1, a2, a3
/// (calibrate/pressure_calibration.hpp) and emit's force law on the image's integral
/// (calibrate/force_calibration.hpp); for contact fitting, the sheet's resistance field, the
/// electrodes' series resistances and the drive voltage from where the presses were
/// (calibrate/sensor_calibration.hpp), then the contact law as the fit sees it on the calibrated
/// sensor (calibrate/contact_law_calibration.hpp).
#include <cstddef>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "emit/calibrate/sensor_calibration.hpp"
#include "emit/frame/reference.hpp"
#include "emit/model/calibration.hpp"
#include "emit/model/method.hpp"
#include "emit/model/reconstruction_model.hpp"
#include "emit/sensor/press.hpp"

namespace emit {

struct PressCalibrationOptions {
  Method method = Method::fit;
  double lambda2 = 0;               ///< the linear operator's λ² (0: the method's)
  double threshold_fraction = 0.5;  ///< of the image's maximum (paper §2.4)
  bool fit_sheet = true;            ///< contact fitting: fit the sheet, electrodes and drive too
  SensorCalibrationOptions sensor;  ///< contact fitting with fit_sheet: what to fit
  std::string cache_dir;            ///< the operator cache (empty: none)
  void validate() const;            ///< \throw InvalidInput naming the option (core/option_check.hpp)
};

struct PressCalibrationResult {
  Calibration calibration;
  std::size_t presses = 0;  ///< the single presses it was fitted on
  /// The calibrated pressure − the true one over those presses [N/mm²].
  double rms_N_per_mm2 = 0, max_abs_N_per_mm2 = 0;
  /// Linear methods: the presses the force law was fitted on (those with a contact) and its mean
  /// |F̂/F − 1| over them.
  std::size_t force_presses = 0;
  double force_error = 0;
  double lambda2 = 0;  ///< the linear operator's λ² (the seeds' operator, for fit)
  /// Contact fitting with fit_sheet: the sensor's fit, and the corrected conductance's range over
  /// the fit mesh as a factor of the nominal.
  std::optional<SensorCalibration> sheet;
  double sheet_factor_low = 1, sheet_factor_high = 1;
};

/// \param frames  one per row of `truth`; frames of one press each are calibrated on, others skipped.
/// \throw InvalidInput (frames and truth of different lengths, no single presses, too few of
/// them), SolverError.
PressCalibrationResult calibrate_from_presses(const Sensor& sensor, const PressCalibrationOptions& options,
                                              const Reference& reference, const std::vector<Frame>& frames,
                                              const PressSequence& truth,
                                              const std::function<void(const std::string&)>& progress = {});

/// The linear methods' calibration on `model` as built (its operator, its λ²): eq. 8 fitted to the
/// single presses' pressures and emit's force law to their contacts' integrals of the image (the
/// contact nearest each press; presses without a contact, or whose contact's integral is not
/// positive, are left out of the force law).
/// calibrate_from_presses calls it for a linear method; the evaluation, on its own models.
/// \throw InvalidInput (frames and truth of different lengths, too few single presses or presses
/// with a contact, all of one force), SolverError.
PressCalibrationResult calibrate_linear(const ReconstructionModel& model, double threshold_fraction,
                                        const Reference& reference, const std::vector<Frame>& frames,
                                        const PressSequence& truth);

}  // namespace emit
