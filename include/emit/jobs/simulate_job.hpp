#pragma once
/// \file simulate_job.hpp
/// `emit simulate`: frames from the digital twin for given presses or a press script, written as
/// CSV with the presses beside them (the ground truth), and on request a picture of the
/// probing layer's potential per frame.
#include <optional>
#include <string>
#include <vector>

#include "emit/core/progress.hpp"
#include "emit/mesh/mesh_quality.hpp"
#include "emit/sensor/press.hpp"
#include "emit/twin/press_scripts.hpp"
#include "emit/twin/realistic_sheet.hpp"
#include "emit/twin/twin.hpp"

namespace emit {

struct SimulateJob {
  std::string sensor_path;  ///< empty: the built-in default sensor
  std::string out_path;     ///< frames (CSV)
  std::string truth_path;   ///< the presses (CSV); empty: <out's stem>_presses.csv beside it
  std::string images_dir;   ///< empty: no pictures
  /// One frame of these presses, or the script's frames: exactly one of the two.
  std::vector<Press> presses;
  std::optional<PressScript> script;
  TwinOptions twin;
  double noise_V = -1;  ///< ≥ 0: replaces the sensor's ADC noise
  /// A realistic sheet (realistic_sheet.hpp) instead of the nominal one; what it drew goes to
  /// `sheet_path` (empty: <out's stem>_sheet.json beside it) as JSON.
  std::optional<RealisticSheetOptions> realistic;
  std::string sheet_path;
};

struct SimulateReport {
  Sensor sensor;  ///< as described (with --noise-V); a realistic sheet's own is in `realistic`
  PressSequence presses;
  std::vector<Frame> frames;
  MeshQuality twin_mesh;
  std::string truth_path;                   ///< where the presses went
  std::optional<RealisticSheet> realistic;  ///< what the realistic sheet drew
  std::string sheet_path;                   ///< where that went (realistic only)
};

/// \throw InvalidInput (neither or both of presses and script, a press off the sheet, a script of
/// more frames than a run holds: core/limits.hpp, before any work), IoError (an output folder
/// that does not exist: before any work).
SimulateReport run_simulate_job(const SimulateJob& job, const Progress& progress = {});

}  // namespace emit
