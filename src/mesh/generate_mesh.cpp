#include "emit/mesh/generate_mesh.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <stdexcept>

#include "emit/core/errors.hpp"
#include "emit/core/option_check.hpp"
#include "emit/core/quote_input.hpp"
#include "emit/mesh/cylinder.hpp"
#include "emit/mesh/flatness.hpp"
#include "emit/mesh/mesh_io.hpp"
#include "emit/mesh/spherical_cap.hpp"
#include "emit/mesh/step_file_check.hpp"
#include "emit/mesh/stl_sheet.hpp"
#include "emit/sensor/surface.hpp"
#include "gmsh_mesher.hpp"
#include "sheet_file_access.hpp"
#include "triangle_estimate.hpp"

namespace emit {

MeshOptions reconstruction_mesh_options(const Sensor& sensor) {
  MeshOptions options;
  options.element_size_mm = sensor.mesh.element_size_mm;
  options.max_triangles = sensor.mesh.max_triangles;
  options.smoothing_steps = 0;  // homogeneous Frontal-Delaunay needs none (MeshOptions says why)
  return options;
}

MeshOptions twin_mesh_options(const Sensor& sensor, int seed) {
  MeshOptions options;
  options.element_size_mm = sensor.mesh.element_size_mm / sensor.mesh.twin_refinement;
  options.max_triangles = sensor.mesh.max_triangles;
  // Grade into the electrodes' ends, where the potential's gradient is singular.
  options.electrode_edge_size_factor = 0.25;
  options.seed = seed;
  return options;
}

Mesh generate_mesh(const Sensor& sensor, const MeshOptions& options) {
  const bool cad = sensor.shape.kind == ShapeKind::mesh_file && is_cad_file(sensor.shape.mesh_path);
  if (sensor.shape.kind == ShapeKind::mesh_file && !cad) {
    // A file's sheet is read, not made: its triangles are counted against the same limit.
    Sensor limited = sensor;
    limited.mesh.max_triangles = options.max_triangles;
    Mesh mesh = is_stl_file(sensor.shape.mesh_path) ? read_stl_sheet(limited)
                                                    : read_msh(sensor.shape.mesh_path, options.max_triangles);
    // Presses and contacts on a curved file's sheet are placed through its surface, read with the
    // sensor (mesh/sheet_file.hpp): without it a press would miss the sheet.
    if (!is_flat(mesh) && !sensor.shape.surface)
      throw InvalidInput(quote_input(sensor.shape.mesh_path) +
                         ": a curved surface whose sensor was read without it (mesh/sheet_file.hpp load_sheet_sensor)");
    return mesh;
  }
  options.validate();
  if (cad) detail::check_sheet_file_access(sensor.shape.mesh_path, "CAD file");
  if (cad && is_step_file(sensor.shape.mesh_path)) check_step_file(sensor.shape.mesh_path);
  detail::check_triangle_estimate(sensor, options);
  // A cap: its disc, at the size that the wrapping's stretch brings back to the element size.
  const bool cap = sensor.shape.kind == ShapeKind::spherical_cap;
  MeshOptions flat = options;
  if (cap) flat.element_size_mm /= spherical_cap_stretch(sensor.shape.sphere_radius_mm, sensor.shape.radius_mm);
  Mesh mesh = detail::gmsh_mesher().mesh_sheet(sensor, flat);
  if (cap) wrap_onto_spherical_cap(mesh, sensor.shape.sphere_radius_mm, sensor.shape.radius_mm);
  // A cylinder's chart is meshed at the element size itself (the map keeps lengths): wrap it, and
  // on a sleeve merge the seam's nodes, keeping the chart's numbering for locality.
  if (sensor.shape.kind == ShapeKind::cylinder) wrap_onto_cylinder(mesh, sensor.shape);
  return mesh;
}

void MeshOptions::validate() const {
  option_check::positive("MeshOptions", "element_size_mm", element_size_mm);
  option_check::positive("MeshOptions", "electrode_edge_size_factor", electrode_edge_size_factor);
  option_check::at_least("MeshOptions", "smoothing_steps", smoothing_steps, 0);
  option_check::positive("MeshOptions", "max_triangles", max_triangles);
}
}  // namespace emit
