#include "emit/model/fit_model.hpp"

#include "emit/mesh/generate_mesh.hpp"
#include "emit/mesh/slide_electrodes.hpp"

namespace emit {

Mesh fit_mesh(const Sensor& sensor) {
  MeshOptions options = reconstruction_mesh_options(sensor);
  options.electrode_edge_size_factor = 0.25;
  options.smoothing_steps = 1;  // graded like the twin's mesh, so smoothed like it
  return generate_mesh(sensor, options);
}

DenseGreenFunction fit_green_function(const Mesh& fit_mesh, const Sensor& sensor, const SheetCorrection* correction) {
  const double resistance = sensor.sheet_resistance_ohm_per_sq;
  return correction ? dense_green_function(fit_mesh, correction->element_conductance_S(fit_mesh, resistance))
                    : dense_green_function(fit_mesh, resistance);
}

FitModel build_fit_model(const Sensor& sensor, const SheetCorrection* correction,
                         const std::function<void(const std::string&)>& progress,
                         const std::vector<double>& electrode_shift_mm) {
  if (progress) progress("meshing the sheet for contact fitting");
  FitModel model{fit_mesh(sensor), {}};
  if (!electrode_shift_mm.empty()) model.mesh = slide_electrodes(model.mesh, sensor, electrode_shift_mm);
  if (progress) progress("Green's function (" + std::to_string(model.mesh.node_count()) + " nodes)");
  model.green = fit_green_function(model.mesh, sensor, correction);
  return model;
}

}  // namespace emit
