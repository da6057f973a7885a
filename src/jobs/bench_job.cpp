#include "emit/jobs/bench_job.hpp"
#include "emit/mesh/sheet_file.hpp"

#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstdio>
#include <filesystem>

#include <nlohmann/json.hpp>

#include "emit/core/errors.hpp"
#include "emit/sensor/sensor_json.hpp"

namespace emit {

namespace {

// The baselines grow as K³ (the K×K Cholesky: ~8 s at 6.8k triangles) and as K·N sparse solves
// (the brute-force Jacobian: ~1 min at 2.5k); above these sizes they would take the run over.
constexpr long max_normal_equations_triangles = 7000;
constexpr long max_brute_force_triangles = 2500;

/// The sensor with `count` electrodes by the default layout, at its own electrode width.
Sensor with_electrodes(const Sensor& sensor, int count) {
  if (count == sensor.electrode_count()) return sensor;
  if (sensor.shape.kind == ShapeKind::mesh_file)
    throw InvalidInput("--electrodes: a mesh-file sensor keeps its own electrodes");
  nlohmann::json j = sensor_to_json(sensor);
  j["electrodes"] = {{"count", count}, {"width_mm", sensor.electrodes.at(0).width_mm}};
  return parse_sensor(j, "--electrodes " + std::to_string(count));
}

/// What a child sends back: its result, or the error that stopped it.
template <class Result>
struct ChildReport {
  Result result;
  char error[240] = "";
};

/// Runs `work` in a child process, so the peak memory measured is its own.
/// \return the child's report; `peak_MiB` its peak resident memory.
template <class Result, class Work>
ChildReport<Result> run_in_child(Work&& work, double& peak_MiB) {
  int channel[2];
  if (::pipe(channel) != 0) throw IoError("bench: cannot create a pipe");
  std::fflush(nullptr);
  const pid_t child = ::fork();
  if (child < 0) throw IoError("bench: cannot fork");
  if (child == 0) {
    ::close(channel[0]);
    ChildReport<Result> report;
    try {
      report.result = work();
    } catch (const std::exception& e) {
      std::snprintf(report.error, sizeof report.error, "%s", e.what());
    }
    const bool sent = ::write(channel[1], &report, sizeof report) == static_cast<ssize_t>(sizeof report);
    ::_exit(sent ? 0 : 1);
  }
  ::close(channel[1]);
  ChildReport<Result> report;
  const bool received = ::read(channel[0], &report, sizeof report) == static_cast<ssize_t>(sizeof report);
  ::close(channel[0]);
  int status = 0;
  rusage usage{};
  ::wait4(child, &status, 0, &usage);
  peak_MiB = static_cast<double>(usage.ru_maxrss) / 1024.0;  // KiB on Linux
  if (!received)
    std::snprintf(report.error, sizeof report.error, "the process ended without a result (status %d)", status);
  return report;
}

}  // namespace

int run_bench_job(const BenchJob& job, const std::function<void(const BenchRow&)>& on_row, const Progress& progress) {
  const Sensor sensor = load_sheet_sensor(job.sensor_path);
  for (const int size : job.triangles)  // refused now, not after the sizes before it ran
    if (!(size >= 1 && size <= sensor.mesh.max_triangles)) {
      char message[160];
      std::snprintf(message, sizeof message,
                    "--sizes %d: a triangle count must be from 1 to the sensor's mesh.max_triangles, %g", size,
                    sensor.mesh.max_triangles);
      throw InvalidInput(message);
    }
  // A current-injection skin is timed with its own electrodes and protocol.
  const bool eit = sensor.excitation.has_value();
  const std::vector<int> electrode_counts = eit ? std::vector<int>{sensor.electrode_count()} : job.electrodes;
  const std::string scratch =
      (std::filesystem::temp_directory_path() / ("emit-bench-" + std::to_string(::getpid()))).string();
  int failures = 0;
  for (int electrodes : electrode_counts) {
    const Sensor case_sensor = eit ? sensor : with_electrodes(sensor, electrodes);
    for (int size : job.triangles) {
      progress.say("timing " + std::to_string(electrodes) + " electrodes, about " + std::to_string(size) +
                   " triangles");
      BenchRow row;
      row.sensor_name = sensor.name;
      row.current_injection = eit;
      row.electrodes = electrodes;
      row.target_triangles = size;
      PipelineTimingOptions options;
      options.target_triangles = size;
      options.cache_dir = scratch;
      const auto ours = run_in_child<PipelineTiming>(
          [&] { return eit ? time_eit_pipeline(case_sensor, options) : time_pipeline(case_sensor, options); },
          row.peak_MiB);
      row.timing = ours.result;
      row.error = ours.error;
      if (row.error.empty()) {
        options.element_size_mm = ours.result.element_size_mm;  // the same mesh
        const bool normal_equations = job.baselines && ours.result.triangles <= max_normal_equations_triangles;
        const bool brute_force = job.brute_force && ours.result.triangles <= max_brute_force_triangles;
        double baseline_peak_MiB = 0;
        if (normal_equations || brute_force) {
          const auto baselines = run_in_child<
              BaselineTiming>([&] { return time_baselines(case_sensor, options, normal_equations, brute_force); },
                              baseline_peak_MiB);
          row.baselines = baselines.result;
          if (baselines.error[0]) progress.warn(std::string("bench: baseline: ") + baselines.error);
        }
      }
      failures += !row.error.empty();
      on_row(row);
    }
  }
  std::error_code ignored;
  std::filesystem::remove_all(scratch, ignored);
  return failures;
}

}  // namespace emit
