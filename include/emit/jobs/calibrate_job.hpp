#pragma once
/// \file calibrate_job.hpp
/// `emit calibrate`: the calibration of a method from presses of known place and force, read from
/// CSV files and written as JSON (pipeline/press_calibration.hpp); and, from resistance–pressure
/// pairs measured on the materials, the contact law of paper eq. 2.
#include <optional>
#include <string>

#include "emit/calibrate/contact_law_calibration.hpp"
#include "emit/core/progress.hpp"
#include "emit/pipeline/press_calibration.hpp"

namespace emit {

struct CalibrateJob {
  std::string sensor_path;  ///< empty: the built-in default sensor
  /// Presses: no-contact frames, frames of presses, their truth (CSV), and the file to write.
  std::string reference_path, frames_path, truth_path, out_path;
  /// Resistance–pressure pairs (CSV: pressure_N_per_mm2,resistance_ohm; a header line allowed).
  std::string contact_law_path;
  PressCalibrationOptions options;
};

struct CalibrateReport {
  std::optional<PressCalibrationResult> presses;  ///< if frames were given
  std::optional<ContactLawFit> contact_law;       ///< if pairs were given
  std::size_t pairs = 0;
};

/// \throw InvalidInput (nothing to calibrate, a missing input, a bad file, naming it), IoError,
/// SolverError.
CalibrateReport run_calibrate_job(const CalibrateJob& job, const Progress& progress = {});

}  // namespace emit
