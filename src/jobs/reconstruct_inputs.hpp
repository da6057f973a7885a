#pragma once
// Private to jobs/: what a job that reconstructs frames reads besides the frames, checked as
// `emit reconstruct` checks it (reconstruct_job.cpp, export_job.cpp): the calibration, and the
// dead electrodes its frames showed.
#include <optional>
#include <string>
#include <vector>

#include "emit/acquire/electrode_health.hpp"
#include "emit/core/progress.hpp"
#include "emit/model/calibration.hpp"
#include "emit/model/method.hpp"

namespace emit::detail {

/// The calibration at `path` (empty: none), checked against `method` (naming the file); a linear
/// one without a force law is used with a warning through `progress`. \throw InvalidInput, IoError.
std::optional<Calibration> load_job_calibration(const std::string& path, Method method, const Progress& progress);

/// The electrodes to leave out (PipelineOptions::excluded), each told to `progress` as a warning
/// with its reason and the measurements it takes away (2 (N − 1) of an N-electrode frame).
std::vector<int> leave_out_dead(const std::vector<DeadElectrode>& dead, int electrode_count, const Progress& progress);

}  // namespace emit::detail
