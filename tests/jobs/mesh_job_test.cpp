// `emit mesh`'s job (jobs/mesh_job.hpp): the twin's graded mesh or the reconstruction's, at the
// size asked, written and read back whole, its quality the file's.
#include "emit/jobs/mesh_job.hpp"

#include <gtest/gtest.h>

#include "emit/mesh/mesh_io.hpp"
#include "test_support.hpp"

namespace emit {
namespace {

TEST(MeshJob, WritesTheMeshItReports) {
  const std::string dir = test::temp_folder("mesh_job");
  MeshJob job;
  job.sensor_path = test::source_path("examples/sensors/square30.json");
  job.out_path = dir + "/sheet.msh";
  job.element_size_mm = 3;
  const MeshReport plain = run_mesh_job(job);
  EXPECT_EQ(plain.sensor_name, "30 mm");
  EXPECT_EQ(plain.electrodes, 16);
  EXPECT_NEAR(plain.quality.total_area_mm2, 30.0 * 30.0, 1e-9 * 900);  // the square, tiled exactly
  const Mesh read = read_msh(job.out_path);
  EXPECT_EQ(read.triangle_count(), plain.quality.triangle_count);
  EXPECT_EQ(read.electrode_count(), 16);

  // The twin's mesh is graded into the electrodes' ends: more triangles at the same element size.
  job.twin = true;
  const MeshReport twin = run_mesh_job(job);
  EXPECT_GT(twin.quality.triangle_count, plain.quality.triangle_count);
  EXPECT_NEAR(twin.quality.total_area_mm2, 900.0, 1e-9 * 900);
}

}  // namespace
}  // namespace emit
