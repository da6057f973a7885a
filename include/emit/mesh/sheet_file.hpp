#pragma once
/// \file sheet_file.hpp
/// A sensor whose sheet is a file's surface (shape "mesh": a Gmsh .msh, or CAD): reading that
/// surface into the sensor, so that its chart names points in 3D (sensor/height_field.hpp).
#include <string>

#include "emit/sensor/sensor.hpp"

namespace emit {

/// The sensor with its file's surface read into shape.surface: a .msh's own triangles, a CAD
/// sheet's reconstruction mesh (generate_mesh.hpp), so that the chart's heights are the
/// reconstruction's. Other sensors, and one already read, come back unchanged.
/// \throw InvalidInput naming the file when its surface is not seen once from +z.
Sensor with_sheet_surface(Sensor sensor);

/// How commands read --sensor: load_sensor (sensor/sensor_json.hpp), then with_sheet_surface; the
/// built-in default sensor for an empty path.
Sensor load_sheet_sensor(const std::string& path);

}  // namespace emit
