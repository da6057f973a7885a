// `emit simulate`'s job (jobs/simulate_job.hpp) without the CLI: the truth written beside the
// frames by default, the noise override, and the checks made before any work.
#include "emit/jobs/simulate_job.hpp"

#include <cmath>
#include <filesystem>

#include <gtest/gtest.h>

#include "emit/core/errors.hpp"
#include "emit/io/frames_csv.hpp"
#include "emit/io/presses_csv.hpp"
#include "emit/sensor/adc.hpp"
#include "test_support.hpp"

namespace emit {
namespace {

SimulateJob coarse_job(const std::string& dir) {
  SimulateJob job;
  job.sensor_path = test::source_path("examples/sensors/square30.json");
  job.out_path = dir + "/frames.csv";
  job.twin.mesh = MeshOptions{2.0, 0.5, 1, 1};  // a coarse graded twin: quick
  return job;
}

// Without noise the twin's ADC is a deterministic rounding: two untouched frames are equal, and
// every value is a whole number of ADC steps (read back from the 7-decimal CSV within 5e-8 V).
TEST(SimulateJob, NoiselessReferencesAreEqualAndQuantised) {
  const std::string dir = test::temp_folder("simulate_job");
  SimulateJob job = coarse_job(dir);
  job.script = PressScript{};  // none: no-contact frames
  job.script->frames = 2;
  job.noise_V = 0;
  const SimulateReport report = run_simulate_job(job);
  EXPECT_EQ(report.sensor.adc.noise_V, 0.0);
  EXPECT_EQ(report.truth_path, (std::filesystem::path(dir) / "frames_presses.csv").string());
  ASSERT_EQ(report.frames.size(), 2u);
  EXPECT_EQ(report.frames[0], report.frames[1]);
  const double step = adc_step_V(report.sensor.adc);
  const auto read = read_frames_csv(job.out_path, 16);
  ASSERT_EQ(read.size(), 2u);
  for (Index i = 0; i < read[0].size(); ++i)
    EXPECT_NEAR(read[0].data()[i], step * std::round(read[0].data()[i] / step), 5e-8 + 1e-12) << i;
  ASSERT_EQ(report.presses.size(), 2u);
  EXPECT_TRUE(report.presses[0].empty() && report.presses[1].empty());
  // A frame without presses writes no row: the truth holds the header alone.
  EXPECT_TRUE(read_presses_csv(report.truth_path).empty());
  EXPECT_GT(report.twin_mesh.triangle_count, 0);
}

template <class Error>
std::string error_of(const SimulateJob& job) {
  try {
    run_simulate_job(job);
  } catch (const Error& e) {
    return e.what();
  }
  return "no error";
}

TEST(SimulateJob, ChecksItsInputsFirst) {
  const std::string dir = test::temp_folder("simulate_job_bad");
  SimulateJob job = coarse_job(dir);
  EXPECT_EQ(error_of<InvalidInput>(job), "nothing to simulate: give --press x,y,r,F or --script NAME");
  job.presses = {{10, 10, 2.5, 5}};
  job.script = PressScript{};
  EXPECT_EQ(error_of<InvalidInput>(job), "give --press or --script, not both");
  job.script.reset();
  job.presses = {{10, 10, 2.5, 5}, {40, 10, 2.5, 5}};
  EXPECT_EQ(error_of<InvalidInput>(job), "frame 0, press 1: centre (40, 10) mm is off the sheet");
  job.presses = {{10, 10, 2.5, 5}};
  job.truth_path = dir + "/no/truth.csv";
  EXPECT_EQ(error_of<IoError>(job),
            "--truth " + dir + "/no/truth.csv: cannot write: folder " + dir + "/no does not exist");
  EXPECT_FALSE(std::filesystem::exists(job.out_path));  // nothing written
}

}  // namespace
}  // namespace emit
