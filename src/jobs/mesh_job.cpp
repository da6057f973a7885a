#include "emit/jobs/mesh_job.hpp"
#include "emit/mesh/sheet_file.hpp"

#include <chrono>
#include <utility>

#include "emit/core/output_paths.hpp"

#include "emit/mesh/generate_mesh.hpp"
#include "emit/mesh/mesh_io.hpp"
#include "emit/sensor/sensor_json.hpp"

namespace emit {

MeshReport run_mesh_job(const MeshJob& job) {
  // --max-triangles holds for a file's sheet too, which is read (and counted) with the sensor.
  Sensor described = job.sensor_path.empty() ? default_sensor() : load_sensor(job.sensor_path);
  if (job.max_triangles > 0) described.mesh.max_triangles = job.max_triangles;
  const Sensor sensor = with_sheet_surface(std::move(described));
  auto outputs = open_outputs({{"--sensor", job.sensor_path}, {"--sensor's mesh file", sensor.shape.mesh_path}},
                              {OutputRequest{{"--out", job.out_path}}});
  MeshOptions options = job.twin ? twin_mesh_options(sensor, job.seed) : reconstruction_mesh_options(sensor);
  if (job.element_size_mm > 0) options.element_size_mm = job.element_size_mm;
  if (job.max_triangles > 0) options.max_triangles = job.max_triangles;
  const auto start = std::chrono::steady_clock::now();
  const Mesh mesh = generate_mesh(sensor, options);
  MeshReport report;
  report.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  report.sensor_name = sensor.name;
  report.quality = measure_mesh_quality(mesh);
  report.electrodes = mesh.electrode_count();
  write_msh(mesh, outputs[0]);
  commit_outputs(outputs);
  return report;
}

}  // namespace emit
