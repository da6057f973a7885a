#include "emit/fit/fit_model.hpp"

#include "emit/mesh/generate_mesh.hpp"

namespace emit {

FitModel build_fit_model(const Sensor& sensor, const std::function<void(const std::string&)>& progress) {
  if (progress) progress("meshing the sheet for contact fitting");
  MeshOptions options = reconstruction_mesh_options(sensor);
  options.electrode_edge_size_factor = 0.25;
  FitModel model{generate_mesh(sensor, options), {}};
  if (progress) progress("Green's function (" + std::to_string(model.mesh.node_count()) + " nodes)");
  model.green = dense_green_function(model.mesh, sensor.sheet_resistance_ohm_per_sq);
  return model;
}

}  // namespace emit
