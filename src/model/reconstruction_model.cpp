#include "emit/model/reconstruction_model.hpp"

#include "emit/mesh/generate_mesh.hpp"
#include "emit/model/image_noise.hpp"
#include "emit/model/jacobian.hpp"
#include "emit/model/operator_cache.hpp"
#include "emit/sensor/adc.hpp"

namespace emit {

ReconstructionModel build_reconstruction_model(const Sensor& sensor, const OperatorOptions& options,
                                               const std::string& cache_dir, const std::vector<int>& excluded,
                                               const std::function<void(const std::string&)>& progress) {
  auto say = [&](const std::string& stage) {
    if (progress) progress(stage);
  };
  options.validate();  // before the mesh and the Jacobian are made for it
  ReconstructionModel model;
  model.options = options;
  model.uncalibrated = LinearCalibration::uncalibrated(sensor);
  model.reading_noise_V = reading_noise_V(sensor.adc);
  model.clipped_at_V = clipped_at_V(sensor.adc);
  say("meshing");
  model.mesh = generate_mesh(sensor, reconstruction_mesh_options(sensor));
  model.surface = sensor.shape;
  model.measurements = make_measurement_set(model.mesh.electrode_count(), excluded);
  const std::string key = operator_cache_key(sensor, model.mesh, model.measurements, options);
  if (!cache_dir.empty()) {
    if (auto cached = load_cached_operator(cache_dir, key);
        cached && cached->rows() == model.mesh.triangle_count() && cached->cols() == model.measurements.size()) {
      model.op = std::move(*cached);
      model.options.lambda2 = model.op.lambda2();
      model.loaded_from_cache = true;
      say("loaded the operator from the cache");
      return model;
    }
  }
  say("computing the Jacobian");
  Matrix J = compute_jacobian(model.mesh, model.measurements);
  say("building the operator");
  model.op = build_compact_operator(std::move(J), model.mesh, options);
  model.options.lambda2 = model.op.lambda2();  // the λ² chosen, when it was left to the rule
  if (!cache_dir.empty()) store_cached_operator(cache_dir, key, model.op);
  return model;
}

}  // namespace emit
