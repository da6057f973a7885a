#include "test_support.hpp"

#include <sys/wait.h>
#include <unistd.h>
#include <array>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "emit/core/errors.hpp"
#include "emit/mesh/generate_mesh.hpp"
#include "emit/sensor/sensor_json.hpp"

namespace emit::test {

Mesh strip_mesh(double width_mm, double height_mm, int nx, int ny) {
  Mesh mesh;
  mesh.nodes_mm.resize(Index{nx + 1} * (ny + 1), 3);
  auto node = [&](int i, int j) { return j * (nx + 1) + i; };
  for (int j = 0; j <= ny; ++j)
    for (int i = 0; i <= nx; ++i) mesh.nodes_mm.row(node(i, j)) << width_mm * i / nx, height_mm * j / ny, 0.0;
  mesh.triangles.resize(Index{2} * nx * ny, 3);
  int t = 0;
  for (int j = 0; j < ny; ++j)
    for (int i = 0; i < nx; ++i) {
      const int a = node(i, j), b = node(i + 1, j), c = node(i + 1, j + 1), d = node(i, j + 1);
      if ((i + j) % 2 == 0) {
        mesh.triangles.row(t++) << a, b, c;
        mesh.triangles.row(t++) << a, c, d;
      } else {
        mesh.triangles.row(t++) << a, b, d;
        mesh.triangles.row(t++) << b, c, d;
      }
    }
  mesh.electrode_nodes.resize(2);
  for (int i = 0; i <= nx; ++i) {
    mesh.electrode_nodes[0].push_back(node(i, 0));
    mesh.electrode_nodes[1].push_back(node(i, ny));
  }
  return mesh;
}

std::string source_path(const std::string& relative) { return std::string(EMIT_SOURCE_DIR) + "/" + relative; }
std::string cli_path() { return EMIT_CLI_PATH; }
std::string real_data_dir() { return EMIT_REAL_DATA_DIR; }

const Sensor& dome_sensor() {
  static const Sensor sensor = load_sensor(source_path("examples/sensors/dome25.json"));
  return sensor;
}

const Mesh& dome_mesh() {
  static const Mesh mesh = generate_mesh(dome_sensor(), reconstruction_mesh_options(dome_sensor()));
  return mesh;
}

std::string temp_folder(const std::string& name) {
  const auto folder = std::filesystem::temp_directory_path() / ("emit_test_" + std::to_string(::getpid()) + "_" + name);
  std::filesystem::remove_all(folder);
  std::filesystem::create_directories(folder);
  return folder.string();
}

std::string read_text(const std::string& path) {
  std::ifstream in(path);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

CommandResult run_emit(const std::string& arguments, const std::string& environment) {
  const std::string folder = temp_folder("run");
  const std::string out = folder + "/stdout", err = folder + "/stderr";
  const std::string command =
      environment + " " + std::string(EMIT_CLI_PATH) + " " + arguments + " >" + out + " 2>" + err + " </dev/null";
  const int status = std::system(command.c_str());
  CommandResult result;
  result.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  result.out = read_text(out);
  result.err = read_text(err);
  std::filesystem::remove_all(folder);
  return result;
}

std::string error_of(const std::function<void()>& call) {
  try {
    call();
  } catch (const Error& e) {
    return e.what();
  }
  return "no error";
}

}  // namespace emit::test
