#include "emit/pipeline/pipeline.hpp"

#include "emit/core/errors.hpp"
#include "emit/core/option_check.hpp"
#include "emit/mesh/mesh_io.hpp"
#include "emit/sensor/sensor.hpp"

namespace emit {

namespace {

OperatorOptions linear_options(const PipelineOptions& options) {
  options.validate();  // a λ² below 0 or not a number is refused, not taken for the default
  OperatorOptions linear = operator_options(options.method);
  if (options.lambda2 > 0) linear.lambda2 = options.lambda2;
  return linear;
}

}  // namespace

int electrode_count_of(const Sensor& sensor) {
  if (sensor.shape.kind != ShapeKind::mesh_file) return sensor.electrode_count();
  if (is_cad_file(sensor.shape.mesh_path) || is_stl_file(sensor.shape.mesh_path))
    return static_cast<int>(sensor.shape.electrode_at_mm.size());
  return read_msh(sensor.shape.mesh_path, sensor.mesh.max_triangles).electrode_count();
}

void check_calibration_for_method(const Calibration& calibration, Method method, const std::string& source) {
  if (is_linear(method) != std::holds_alternative<LinearCalibration>(calibration))
    throw InvalidInput(source + ": a calibration for " + calibration_kind(calibration) +
                       "; run 'emit calibrate --method " + method_name(method) + "'");
}

Pipeline::Pipeline(const Sensor& sensor, const PipelineOptions& options, const std::optional<Calibration>& calibration,
                   const std::function<void(const std::string&)>& progress, const std::string& calibration_source)
    : method_(options.method), calibrated_(calibration.has_value()), fit_sensor_(sensor) {
  // The commands say so first, naming the file; a library caller (Python) hears it here.
  require_emit_protocol(sensor, "sensor \"" + sensor.name + "\"");
  if (calibration) check_calibration_for_method(*calibration, method_, calibration_source);
  model_ = build_reconstruction_model(sensor, linear_options(options), options.cache_dir, options.excluded, progress);
  linear_ = model_.uncalibrated;
  if (is_linear(method_)) {
    if (calibration) linear_ = std::get<LinearCalibration>(*calibration);
    return;
  }
  fit_calibration_ = calibration ? std::get<FitCalibration>(*calibration) : FitCalibration::uncalibrated(sensor);
  const int N = model_.measurements.electrode_count;
  if (fit_calibration_.electrode_count > 0 && fit_calibration_.electrode_count != N)
    throw InvalidInput(calibration_source + ": a calibration of a sensor with " +
                       std::to_string(fit_calibration_.electrode_count) + " electrodes; this one has " +
                       std::to_string(N));
  if (!fit_calibration_.electrode_shift_mm.empty() && static_cast<int>(fit_calibration_.electrode_shift_mm.size()) != N)
    throw InvalidInput(calibration_source + ": electrode_shift_mm has " +
                       std::to_string(fit_calibration_.electrode_shift_mm.size()) + " values for " + std::to_string(N) +
                       " electrodes");
  if (!fit_calibration_.series_resistance_ohm.empty() &&
      static_cast<int>(fit_calibration_.series_resistance_ohm.size()) != N)
    throw InvalidInput(calibration_source + ": series_resistance_ohm has " +
                       std::to_string(fit_calibration_.series_resistance_ohm.size()) + " values for " +
                       std::to_string(N) + " electrodes");
  fit_sensor_ = fit_calibration_.applied_to(sensor);
  fit_model_ = std::make_unique<FitModel>(
      build_fit_model(sensor, fit_calibration_.sheet_correction ? &*fit_calibration_.sheet_correction : nullptr,
                      progress, fit_calibration_.electrode_shift_mm));
  fit_.emplace(fit_sensor_, fit_model_->mesh, fit_model_->green, model_.measurements);
}

void check_frame_options(Method method, const FrameOptions& options) {
  options.validate();
  if (options.contact_radius_mm > 0 && is_linear(method))
    throw InvalidInput(std::string("a declared contact radius is for contact fitting (fit, shapes), which holds a "
                                   "contact's area; ") +
                       method_name(method) + "'s comes from its image");
}

Reconstructor Pipeline::reconstructor(const FrameOptions& options) const {
  check_frame_options(method_, options);
  if (fit_) {
    FrameOptions o = options;
    o.contact_shapes = o.contact_shapes || method_ == Method::shapes;
    return Reconstructor(model_, *fit_, fit_calibration_, o);
  }
  return Reconstructor(model_, linear_, options);
}

namespace {

FrameOptions independent_frames(FrameOptions options) {
  options.track_contacts = false;
  return options;
}

}  // namespace

std::vector<std::vector<Contact>> Pipeline::reconstruct_batch(const FrameOptions& options, const Reference& reference,
                                                              const std::vector<Frame>& frames, int threads) const {
  const FrameOptions independent = independent_frames(options);
  return emit::reconstruct_batch([&] { return reconstructor(independent); }, reference, frames, threads);
}

std::vector<std::vector<Contact>> Pipeline::reconstruct_batch(const FrameOptions& options, const Reference& reference,
                                                              std::span<const double> frames_volts, int threads) const {
  const FrameOptions independent = independent_frames(options);
  return emit::reconstruct_batch([&] { return reconstructor(independent); }, reference, frames_volts,
                                 model_.measurements.electrode_count, threads);
}

void PipelineOptions::validate() const {
  option_check::zero_or_positive("PipelineOptions", "lambda2", lambda2, "the method's");
  for (const int electrode : excluded) option_check::at_least("PipelineOptions", "excluded", electrode, 0);
}
}  // namespace emit
