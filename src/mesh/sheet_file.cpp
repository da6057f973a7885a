#include "emit/mesh/sheet_file.hpp"

#include <memory>

#include "emit/core/quote_input.hpp"
#include "emit/mesh/generate_mesh.hpp"
#include "emit/mesh/mesh_io.hpp"
#include "emit/mesh/stl_sheet.hpp"
#include "emit/sensor/sensor_json.hpp"

namespace emit {

Sensor with_sheet_surface(Sensor sensor) {
  if (sensor.shape.kind != ShapeKind::mesh_file || sensor.shape.surface) return sensor;
  // A CAD sheet's reconstruction mesh; a .msh or STL surface is its own.
  const std::string& path = sensor.shape.mesh_path;
  const Mesh mesh = is_cad_file(path)   ? generate_mesh(sensor, reconstruction_mesh_options(sensor))
                    : is_stl_file(path) ? read_stl_sheet(sensor)
                                        : read_msh(path, sensor.mesh.max_triangles);
  sensor.shape.surface =
      std::make_shared<const HeightField>(mesh.nodes_mm, mesh.triangles, quote_input(sensor.shape.mesh_path, 120));
  return sensor;
}

Sensor load_sheet_sensor(const std::string& path) {
  return path.empty() ? default_sensor() : with_sheet_surface(load_sensor(path));
}

}  // namespace emit
