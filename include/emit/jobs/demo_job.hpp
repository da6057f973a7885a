#pragma once
/// \file demo_job.hpp
/// `emit demo`'s first part, the main job on the built-in sensor: its digital twin stands in for a
/// real sheet and records a reference frame, 20 presses of known force and a few presses to
/// reconstruct (one of them two fingers); contact fitting is calibrated on the 20, and the few
/// are reconstructed by contact fitting and by the paper's method. Writes frames.csv,
/// presses.csv, contacts.jsonl, calibration.json and a pressure map per frame into a folder.
/// (The second part goes live: jobs/live_session.hpp with that calibration.)
#include <string>
#include <vector>

#include "emit/core/progress.hpp"
#include "emit/frame/contacts.hpp"
#include "emit/model/calibration.hpp"
#include "emit/sensor/press.hpp"

namespace emit {

struct DemoReport {
  Sensor sensor;
  std::size_t calibration_presses = 0;
  double twin_seconds = 0, model_seconds = 0;
  long triangles = 0, fit_mesh_nodes = 0;
  FitCalibration calibration;
  PressSequence presses;                     ///< the frames' true presses
  std::vector<std::vector<Contact>> fitted;  ///< per frame, by contact fitting (calibrated)
  std::vector<std::vector<Contact>> paper;   ///< per frame, by the paper's method
  std::string calibration_path;              ///< where the calibration went
};

/// \param out_dir  created if need be. \throw IoError, InvalidInput, SolverError.
DemoReport run_demo_reconstruction(const std::string& out_dir, const std::string& cache_dir,
                                   const Progress& progress = {});

}  // namespace emit
