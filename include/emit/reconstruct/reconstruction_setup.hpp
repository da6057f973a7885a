#pragma once
/// \file reconstruction_setup.hpp
/// Everything built before the first frame for one method, as `emit reconstruct` and `emit live`
/// both need it: the linear model (the paper's operator; contact fitting is seeded by its image),
/// and for `fit` the fit model and its fitter, with the calibrated contact law and sheet.
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "emit/fit/contact_fitter.hpp"
#include "emit/fit/fit_model.hpp"
#include "emit/reconstruct/pressure.hpp"
#include "emit/reconstruct/reconstruction_model.hpp"
#include "emit/reconstruct/reconstructor.hpp"

namespace emit {

struct SetupOptions {
  std::string method = "fit";  ///< fit, paper, noser or laplacian
  double lambda2 = 0;          ///< the linear method's λ² (0: the method's default)
  std::string cache_dir;       ///< the operator cache (empty: none)
  std::vector<int> excluded;   ///< dead electrodes left out
};

/// \throw InvalidInput when `calibration` was made for the other kind of method than `method`
/// (fit, or the linear ones); `path` names the file in the message.
void check_calibration_for_method(const PressureCalibration& calibration, const std::string& method,
                                  const std::string& path);

/// The sensor's electrode count; a mesh-file sensor's electrodes are its file's (read here).
/// \throw InvalidInput, IoError for an unreadable mesh file.
int electrode_count_of(const Sensor& sensor);

class ReconstructionSetup {
 public:
  /// Builds the models (from the operator cache where it can). `progress` is told each stage.
  /// \throw InvalidInput (an unknown method, a mismatched calibration), IoError, SolverError.
  ReconstructionSetup(const Sensor& sensor, PressureCalibration calibration, const SetupOptions& options,
                      const std::function<void(const std::string&)>& progress = {});
  ReconstructionSetup(const ReconstructionSetup&) = delete;
  ReconstructionSetup& operator=(const ReconstructionSetup&) = delete;

  bool fits() const { return fitter_.has_value(); }
  const ReconstructionModel& model() const { return model_; }
  const PressureCalibration& calibration() const { return calibration_; }
  const OperatorOptions& operator_options() const { return model_.options; }

  /// A reconstructor on this set-up, with the fitter attached for `fit`. It (and its fitter)
  /// refer to this set-up, which must outlive it; one reconstructor at a time uses the fitter.
  Reconstructor reconstructor(const FrameOptions& options = {});

 private:
  PressureCalibration calibration_;
  ReconstructionModel model_;
  std::unique_ptr<FitModel> fit_model_;
  Sensor fit_sensor_;  ///< the sensor with the calibrated contact law, if there is one
  std::optional<ContactFitter> fitter_;
};

}  // namespace emit
