#include "emit/reconstruct/reconstruction_setup.hpp"

#include "emit/errors.hpp"
#include "emit/mesh/mesh_io.hpp"

namespace emit {

namespace {

OperatorOptions linear_options(const SetupOptions& options) {
  // Fitting is seeded by the paper method's image.
  OperatorOptions linear = method_options(options.method == "fit" ? "paper" : options.method);
  if (options.lambda2 > 0) linear.lambda2 = options.lambda2;
  return linear;
}

}  // namespace

void check_calibration_for_method(const PressureCalibration& calibration, const std::string& method,
                                  const std::string& path) {
  const bool fit = method == "fit";
  if (calibration.calibrated && fit != calibration.fitted_contact_law.has_value())
    throw InvalidInput(path + ": a calibration for " + (fit ? "the linear methods" : "contact fitting") +
                       "; run 'emit calibrate --method " + method + "'");
}

int electrode_count_of(const Sensor& sensor) {
  return sensor.shape.kind == ShapeKind::mesh_file ? read_msh(sensor.shape.mesh_path).electrode_count()
                                                   : sensor.electrode_count();
}

ReconstructionSetup::ReconstructionSetup(const Sensor& sensor, PressureCalibration calibration,
                                         const SetupOptions& options,
                                         const std::function<void(const std::string&)>& progress)
    : calibration_(std::move(calibration)),
      model_(build_reconstruction_model(sensor, linear_options(options), options.cache_dir, options.excluded, progress)),
      fit_sensor_(sensor) {
  if (options.method != "fit") return;
  if (calibration_.fitted_contact_law) fit_sensor_.contact = *calibration_.fitted_contact_law;
  fit_model_ = std::make_unique<FitModel>(build_fit_model(
      sensor, calibration_.sheet_correction ? &*calibration_.sheet_correction : nullptr, progress));
  fitter_.emplace(fit_sensor_, fit_model_->mesh, fit_model_->green, model_.measurements);
}

Reconstructor ReconstructionSetup::reconstructor(const FrameOptions& options) {
  Reconstructor reconstructor(model_, calibration_, options);
  if (fitter_) reconstructor.use_fitter(&*fitter_);
  return reconstructor;
}

}  // namespace emit
