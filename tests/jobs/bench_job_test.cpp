// `emit bench`'s job (jobs/bench_job.hpp) without timing anything long: a case that fails in its
// child process comes back as a row saying why and is counted; a mesh-file sensor keeps its own
// electrodes. (A whole bench case runs end to end in tests/cli/cli_test.cpp.)
#include "emit/jobs/bench_job.hpp"

#include <fstream>

#include <gtest/gtest.h>

#include "emit/core/errors.hpp"
#include "emit/mesh/generate_mesh.hpp"
#include "emit/mesh/mesh_io.hpp"
#include "emit/sensor/sensor_json.hpp"
#include "test_support.hpp"

namespace emit {
namespace {

// Two sizes too small to bench, with 8 electrodes (the default sensor's 16 re-laid out): each
// child refuses its case, and the rows come back in order with the child's message.
TEST(BenchJob, FailedCasesAreRowsSayingWhy) {
  BenchJob job;
  job.triangles = {50, 60};
  job.electrodes = {8};
  std::vector<BenchRow> rows;
  const int failures = run_bench_job(job, [&](const BenchRow& row) { rows.push_back(row); });
  EXPECT_EQ(failures, 2);
  ASSERT_EQ(rows.size(), 2u);
  EXPECT_EQ(rows[0].electrodes, 8);
  EXPECT_EQ(rows[0].target_triangles, 50);
  EXPECT_EQ(rows[1].target_triangles, 60);
  EXPECT_EQ(rows[0].sensor_name, "default 60 mm");
  EXPECT_EQ(rows[0].error, "bench size must be 100 to 2,000,000 triangles, got 50");
  EXPECT_GT(rows[0].peak_MiB, 0.0);  // the child's own peak, measured even when it failed
}

TEST(BenchJob, AMeshFileSensorKeepsItsElectrodes) {
  const std::string dir = test::temp_folder("bench_job_msh");
  Sensor square = load_sensor(test::source_path("examples/sensors/square30.json"));
  square.electrodes.resize(12);  // a sheet of 12 electrodes, asked for 16
  write_msh(generate_mesh(square, MeshOptions{5.0, 1.0, 0, 0}), dir + "/sheet.msh");
  std::ofstream(dir + "/sensor.json") << R"({"shape": {"type": "mesh", "file": "sheet.msh"}})";
  BenchJob job;
  job.sensor_path = dir + "/sensor.json";
  job.electrodes = {16};
  try {
    run_bench_job(job, [](const BenchRow&) {});
    FAIL() << "no error";
  } catch (const InvalidInput& e) {
    EXPECT_STREQ(e.what(), "--electrodes: a mesh-file sensor keeps its own electrodes");
  }
}

}  // namespace
}  // namespace emit
