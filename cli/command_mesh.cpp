// emit mesh: mesh a sensor's sheet and report the mesh's quality.
#include <chrono>
#include <cstdio>

#include "commands.hpp"
#include "emit/mesh/generate_mesh.hpp"
#include "emit/mesh/mesh_io.hpp"
#include "emit/mesh/mesh_quality.hpp"

namespace emit::cli {

namespace {

struct MeshArgs {
  std::string sensor_path, out_path;
  bool twin = false;
  double element_size_mm = 0;
  int seed = 1;
};

void run_mesh(const MeshArgs& args) {
  const Sensor sensor = sensor_from_option(args.sensor_path);
  MeshOptions options = args.twin ? twin_mesh_options(sensor, args.seed) : reconstruction_mesh_options(sensor);
  if (args.element_size_mm > 0) options.element_size_mm = args.element_size_mm;
  const auto start = std::chrono::steady_clock::now();
  const Mesh mesh = generate_mesh(sensor, options);
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  const MeshQuality q = measure_mesh_quality(mesh);
  write_msh(mesh, args.out_path);
  std::printf("%s mesh of %s: %lld triangles, %lld nodes, %d electrodes; min angle %.1f deg, mean edge %.3f mm, "
              "area %.1f mm2; meshed in %.3f s; wrote %s\n",
              args.twin ? "twin" : "reconstruction", sensor.name.c_str(), static_cast<long long>(q.triangle_count),
              static_cast<long long>(q.node_count), mesh.electrode_count(), q.min_angle_deg, q.mean_edge_mm,
              q.total_area_mm2, seconds, args.out_path.c_str());
}

}  // namespace

void add_mesh_command(CLI::App& app) {
  auto args = std::make_shared<MeshArgs>();
  CLI::App* cmd = app.add_subcommand("mesh", "Mesh a sensor's sheet with Gmsh and write a .msh file");
  cmd->add_option("--sensor", args->sensor_path, "Sensor description (JSON); default: the built-in 60 mm sensor")
      ->check(CLI::ExistingFile);
  cmd->add_option("--out", args->out_path, "Mesh file to write (.msh)")->required();
  cmd->add_flag("--twin", args->twin, "Mesh at the twin's finer, electrode-graded resolution");
  cmd->add_option("--element-size-mm", args->element_size_mm, "Override the sensor's element size")
      ->check(CLI::PositiveNumber);
  cmd->add_option("--seed", args->seed, "Twin mesh seed (another seed, another mesh)");
  cmd->callback([args] { run_mesh(*args); });
}

}  // namespace emit::cli
