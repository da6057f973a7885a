#pragma once
/// \file bench_job.hpp
/// `emit bench`: the paper method's pipeline timed stage by stage (eval/pipeline_timing.hpp) at
/// several mesh sizes and electrode counts, with the naive baselines where they finish in
/// reasonable time. A current-injection skin (its sensor has an "excitation") is timed as pyEIT's
/// and EIDORS's users run it (eval/pipeline_timing.hpp time_eit_pipeline), with its own
/// electrodes: `electrodes` does not apply. Each case runs in a child process of its own, so the peak memory measured
/// is its own.
#include <functional>
#include <string>
#include <vector>

#include "emit/core/progress.hpp"
#include "emit/eval/pipeline_timing.hpp"

namespace emit {

struct BenchJob {
  std::string sensor_path;                                ///< empty: the built-in default sensor
  std::vector<int> triangles{1500, 6000, 24000, 100000};  ///< about, per case
  std::vector<int> electrodes{16, 32};
  bool baselines = true;     ///< the K×K normal equations, up to 7,000 triangles
  bool brute_force = false;  ///< the brute-force Jacobian, up to 2,500 triangles
};

struct BenchRow {
  std::string sensor_name;
  bool current_injection = false;  ///< timed by time_eit_pipeline
  int electrodes = 0, target_triangles = 0;
  PipelineTiming timing;
  BaselineTiming baselines;
  double peak_MiB = 0;  ///< the case's child process's peak resident memory
  std::string error;    ///< why the case failed; empty if it did not
};

/// Calls `on_row` as each case finishes (sizes within an electrode count, electrode counts in
/// turn). \return how many cases failed (their rows say why). \throw InvalidInput (a bad sensor, a mesh-file sensor
/// with another electrode count, a size beyond the sensor's mesh.max_triangles: before any case),
/// IoError (no child process).
int run_bench_job(const BenchJob& job, const std::function<void(const BenchRow&)>& on_row,
                  const Progress& progress = {});

}  // namespace emit
