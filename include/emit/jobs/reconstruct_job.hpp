#pragma once
/// \file reconstruct_job.hpp
/// `emit reconstruct`: frames from a CSV file → contacts as JSON Lines, and on request a pressure
/// map per frame. The frames are read and checked before anything is built or written (a bad
/// value stops the run with nothing lost); dead electrodes are found in them and left out; the
/// contacts file is replaced only when it is whole.
#include <string>
#include <vector>

#include "emit/core/progress.hpp"
#include "emit/frame/contact_tracker.hpp"
#include "emit/model/method.hpp"
#include "emit/render/pressure_map.hpp"

namespace emit {

struct ReconstructJob {
  std::string sensor_path;       ///< empty: the built-in default sensor
  std::string reference_path;    ///< no-contact frames (CSV; averaged)
  std::string frames_path;       ///< frames to reconstruct (CSV)
  std::string contacts_path;     ///< contacts out (JSON Lines); "-": standard output
  std::string tracks_path;       ///< tracked contacts as CSV (io/tracks_csv.hpp); empty: none
  std::string calibration_path;  ///< empty: uncalibrated
  std::string images_dir;        ///< empty: no pictures
  PressureMapOptions images;     ///< how they are drawn
  std::string mcap_path;         ///< empty: no MCAP recording (io/tactile_mcap.hpp)
  Method method = Method::fit;
  double lambda2 = 0;  ///< 0: the method's
  double threshold_fraction = 0.5, min_contact_area_mm2 = 0;
  double contact_radius_mm = 0;  ///< a declared indenter (FrameOptions::contact_radius_mm); 0: none
  std::string cache_dir;         ///< empty: no operator cache
  int threads = 1;               ///< the linear methods' batch is split across them
  /// The frames' rate: frame f is at f / frames_per_s s (a file of frames has no times), for
  /// tracking's velocities and the MCAP recording's stamps.
  double frames_per_s = 50;
  TrackerOptions tracking;  ///< the contacts' ids, phases and velocities (frame/contact_tracker.hpp)
};

struct ReconstructReport {
  std::size_t frames = 0;
  long triangles = 0;
  int measurements = 0;
  bool operator_from_cache = false;
  double model_seconds = 0, frames_per_s = 0;
  double lambda2 = 0;  ///< the linear operator's
  bool calibrated = false;
  std::vector<int> dead_electrodes;  ///< left out (each also told to progress.warning)
  /// Readings masked (a value `nan`/`inf`, or at the ADC's top code: frame/masked_readings.hpp) and
  /// the frames that had any, dead electrodes' readings included.
  long readings_masked = 0, frames_with_masked = 0;
};

/// \throw InvalidInput, IoError, SolverError with one-line messages naming the file.
ReconstructReport run_reconstruct_job(const ReconstructJob& job, const Progress& progress = {});

}  // namespace emit
