#pragma once
/// \file pipeline.hpp
/// The one place that builds every model a method needs, from a sensor and options: the linear
/// model (mesh, Jacobian, operator, from the cache where it can: model/reconstruction_model.hpp),
/// and for contact fitting the fit model (its graded mesh and Green's function, on the calibrated
/// sheet) and the fit's precompute with the calibrated contact law (frame/contact_fitter.hpp).
/// Built once, it is read-only: each reconstructor it makes has its own scratch, so several run
/// at once on as many threads. `emit reconstruct`, `emit live`, the Python bindings and the
/// evaluation all reconstruct through it.
///
/// Example:
///
///     const emit::Pipeline pipeline(sensor, {.method = emit::Method::fit, .cache_dir = emit::default_cache_dir()});
///     emit::Reconstructor reconstructor = pipeline.reconstructor();
///     reconstructor.set_reference(emit::average_reference(untouched_frames));
///     for (const emit::Frame& frame : frames) use(reconstructor.process(frame));
#include <functional>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "emit/frame/batch.hpp"
#include "emit/frame/contact_fitter.hpp"
#include "emit/frame/reconstructor.hpp"
#include "emit/model/calibration.hpp"
#include "emit/model/fit_model.hpp"
#include "emit/model/method.hpp"
#include "emit/model/reconstruction_model.hpp"

namespace emit {

struct PipelineOptions {
  Method method = Method::fit;
  double lambda2 = 0;         ///< the linear operator's λ² (0: the method's, model/method.hpp)
  std::string cache_dir;      ///< the operator cache (empty: none; model/operator_cache.hpp)
  std::vector<int> excluded;  ///< dead electrodes left out (acquire/electrode_health.hpp)
  void validate() const;      ///< \throw InvalidInput naming the option (core/option_check.hpp)
};

/// The sensor's electrode count; a mesh-file sensor's electrodes are its file's (read here).
/// \throw InvalidInput, IoError for an unreadable mesh file.
int electrode_count_of(const Sensor& sensor);

/// \throw InvalidInput "<source>: a calibration for <kind>; run 'emit calibrate --method <m>'"
/// when `calibration` is not of the kind `method` needs (model/calibration.hpp).
void check_calibration_for_method(const Calibration& calibration, Method method, const std::string& source);

/// `options` valid, and for `method`: a declared contact radius (FrameOptions::contact_radius_mm)
/// only for contact fitting, the methods that hold a contact's area (a linear method's comes from
/// its image). \throw InvalidInput naming what is wrong.
void check_frame_options(Method method, const FrameOptions& options);

class Pipeline {
 public:
  /// Builds the models. `calibration`: none is uncalibrated; one of the wrong kind is refused
  /// (check_calibration_for_method, `calibration_source` naming it). `progress` is told each stage.
  /// \throw InvalidInput (a mismatched calibration, a bad sensor, a current-injection skin:
  /// sensor/sensor.hpp's require_emit_protocol), IoError, SolverError.
  Pipeline(const Sensor& sensor, const PipelineOptions& options, const std::optional<Calibration>& calibration = {},
           const std::function<void(const std::string&)>& progress = {},
           const std::string& calibration_source = "calibration");
  Pipeline(const Pipeline&) = delete;
  Pipeline& operator=(const Pipeline&) = delete;
  ~Pipeline() = default;

  Method method() const { return method_; }
  bool calibrated() const { return calibrated_; }
  const ReconstructionModel& model() const { return model_; }
  /// The sensor it was built for (for contact fitting, with the calibrated contact law).
  const Sensor& sensor() const { return fit_sensor_; }
  const OperatorOptions& operator_options() const { return model_.options; }
  /// The linear method's calibration (the uncalibrated eq. 8 until calibrated). \pre is_linear(method()).
  const LinearCalibration& linear_calibration() const { return linear_; }
  /// Contact fitting's own mesh (model/fit_model.hpp); null for a linear method.
  const Mesh* fit_mesh() const { return fit_model_ ? &fit_model_->mesh : nullptr; }

  /// Contact fitting's shared precompute (frame/contact_fitter.hpp); null for a linear method.
  const FitPrecompute* fit_precompute() const { return fit_ ? &*fit_ : nullptr; }

  /// A reconstructor for the method, with its own scratch (for `fit`, its own fitter on the
  /// pipeline's precompute): several may run at once, on as many threads. Each refers to this
  /// pipeline, which must outlive it. \throw InvalidInput for a bad option (check_frame_options).
  Reconstructor reconstructor(const FrameOptions& options = {}) const;

  /// Independent frames on `threads` workers, every method (frame/batch.hpp): for `fit`, each
  /// frame is fitted cold (options.track_contacts is set false), so that the contacts do not
  /// depend on the thread count. \throw as reconstruct_batch.
  std::vector<std::vector<Contact>> reconstruct_batch(const FrameOptions& options, const Reference& reference,
                                                      const std::vector<Frame>& frames, int threads) const;
  /// The same over one block of frames (a C-ordered (frames, N, N) array), read in place.
  std::vector<std::vector<Contact>> reconstruct_batch(const FrameOptions& options, const Reference& reference,
                                                      std::span<const double> frames_volts, int threads) const;

 private:
  Method method_;
  bool calibrated_;
  ReconstructionModel model_;
  LinearCalibration linear_;
  FitCalibration fit_calibration_;
  std::unique_ptr<FitModel> fit_model_;
  Sensor fit_sensor_;  ///< the sensor with the calibrated contact law
  std::optional<FitPrecompute> fit_;
};

}  // namespace emit
