#pragma once
// Helpers shared by the tests: meshes built without Gmsh (so FEM tests do not depend on the
// mesher), paths to the repository's data, and a CLI runner for end-to-end tests.
#include <functional>
#include <string>

#include "emit/mesh/mesh.hpp"
#include "emit/sensor/sensor.hpp"

namespace emit::test {

/// Structured mesh of [0,w]×[0,h] with nx×ny cells, each split into two triangles along
/// alternating diagonals. Electrode 0 is the whole bottom side, electrode 1 the whole top side.
Mesh strip_mesh(double width_mm, double height_mm, int nx, int ny);

std::string source_path(const std::string& relative);
/// This build's emit command, and the folder of real skins' data sets (CMake's EMIT_REAL_DATA_DIR).
std::string cli_path();
std::string real_data_dir();

/// The example dome (examples/sensors/dome25.json) and its reconstruction mesh (Gmsh), made once.
const Sensor& dome_sensor();
const Mesh& dome_mesh();

struct CommandResult {
  int exit_code = -1;
  std::string out, err;
};
/// Run the emit CLI with these arguments (a shell-quoted string), capturing stdout and stderr;
/// `environment`: shell assignments put before the command (VAR=value ...).
CommandResult run_emit(const std::string& arguments, const std::string& environment = "");

/// A fresh, empty temporary folder for one test.
std::string temp_folder(const std::string& name);

std::string read_text(const std::string& path);

/// The message of the emit error (core/errors.hpp) that `call` throws, or "no error".
std::string error_of(const std::function<void()>& call);

}  // namespace emit::test
