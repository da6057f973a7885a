// emit mesh: mesh a sensor's sheet and report the mesh's quality.
#include <cstdio>

#include "commands.hpp"
#include "emit/jobs/mesh_job.hpp"

namespace emit::cli {

void add_mesh_command(CLI::App& app) {
  auto job = std::make_shared<MeshJob>();
  CLI::App* cmd = app.add_subcommand("mesh", "Mesh a sensor's sheet with Gmsh and write a .msh file");
  cmd->footer("Example:\n  emit mesh --sensor examples/sensors/circle40.json --out circle.msh");
  cmd->add_option("--sensor", job->sensor_path, "Sensor description (JSON); default: the built-in 60 mm sensor")
      ->check(CLI::ExistingFile);
  cmd->add_option("--out", job->out_path, "Mesh file to write (.msh)")->required();
  cmd->add_flag("--twin", job->twin, "Mesh at the twin's finer, electrode-graded resolution");
  cmd->add_option("--element-size-mm", job->element_size_mm, "Override the sensor's element size")
      ->check(positive_number());
  cmd->add_option("--max-triangles", job->max_triangles,
                  "Refuse beyond this many triangles (default: the sensor's, 1e6)")
      ->check(positive_number());
  cmd->add_option("--seed", job->seed, "Twin mesh seed (another seed, another mesh)");
  cmd->callback([job] {
    const MeshReport r = run_mesh_job(*job);
    const MeshQuality& q = r.quality;
    std::printf(
        "%s mesh of %s: %lld triangles, %lld nodes, %d electrodes; min angle %.1f deg, mean edge %.3f mm, "
        "area %.1f mm2; meshed in %.3f s; wrote %s\n",
        job->twin ? "twin" : "reconstruction", r.sensor_name.c_str(), static_cast<long long>(q.triangle_count),
        static_cast<long long>(q.node_count), r.electrodes, q.min_angle_deg, q.mean_edge_mm, q.total_area_mm2,
        r.seconds, job->out_path.c_str());
  });
}

}  // namespace emit::cli
