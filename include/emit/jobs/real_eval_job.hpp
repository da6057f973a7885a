#pragma once
/// \file real_eval_job.hpp
/// `emit eval --real DIR --sensor S`: a real current-injection skin's presses (io/real_dataset.hpp)
/// calibrated on the first N and located after (eval/real_evaluation.hpp); the contacts of every
/// later press written as JSON Lines ("frame" = the row of frames.csv), and the held-out error
/// against the number of calibration presses drawn as a plot.
#include <string>

#include "emit/core/progress.hpp"
#include "emit/eval/real_evaluation.hpp"

namespace emit {

struct RealEvalJob {
  std::string folder;         ///< the presses (frames.csv, references, truth.csv)
  std::string sensor_path;    ///< the skin, with its "excitation"
  std::string contacts_path;  ///< JSON Lines of the located presses; empty: not written
  std::string plots_dir;      ///< the error-versus-calibration plot's folder; empty: none
  RealEvalOptions options;
};

struct RealEvalReport {
  RealEvaluation evaluation;
  std::string sensor_name;
  std::string plot_path;  ///< empty when no plot was asked for
};

/// \throw IoError (a missing file or folder, an output that cannot be written), InvalidInput (a
/// malformed file, a sensor without an excitation or with other readings, a bad option).
RealEvalReport run_real_eval_job(const RealEvalJob& job, const Progress& progress = {});

}  // namespace emit
