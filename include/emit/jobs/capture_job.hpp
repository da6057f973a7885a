#pragma once
/// \file capture_job.hpp
/// `emit calibrate --capture SOURCE`: a calibration captured by hand from the board (issue 33), no
/// robot and no XY stage. It walks a person through it, one line per step:
///  1. "Lift everything off the sheet": quiet_frames frames, the reference (their robust mean) and
///     a reading's noise measured from them;
///  2. "Press anywhere, one finger at a time": each stable press found in the stream
///     (frame/press_segmenter.hpp) is counted and placed roughly by the nominal contact fit (as
///     `emit reconstruct` does, uncalibrated) on a coverage map of the sheet, until `presses` or every
///     cell is covered (from the twin's scripted person, sim:calibration[:N], which does not hear the
///     prompts: its own N, and the weights it puts down are the default 2 and 5 N);
///  3. "Put the 2.00 N weight down anywhere, then lift it", for each known weight: the next stable
///     press is that weight (known force, unknown place);
///  4. the calibration (jobs/calibrate_job.hpp) from what it captured.
/// What it captures goes to capture_dir as it comes: reference.csv (the quiet frames), frames.csv
/// (one frame per press: its stable run's mean) and presses.csv (places empty; forces empty for the
/// fingers, the weight's for a weight: io/presses_csv.hpp), each rewritten whole after every press,
/// so that a stop (Ctrl-C) or a source that ends leaves complete files to calibrate from offline.
#include <atomic>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "emit/acquire/frame_source.hpp"
#include "emit/frame/press_segmenter.hpp"
#include "emit/jobs/calibrate_job.hpp"

namespace emit {

struct CaptureJob {
  std::string source_spec;  ///< any live source (live/open_source.hpp): serial:PORT, file:REC, sim:…
  SourceOptions source;
  /// The calibration to run after: sensor_path, out_path and options are used; its reference,
  /// frames and truth paths are the capture's files.
  CalibrateJob calibrate;
  std::string capture_dir;                     ///< empty: beside calibrate.out_path, "<out without .json>_capture"
  int quiet_frames = 25;                       ///< step 1's frames (0.5 s at 50 frames/s)
  int presses = 60;                            ///< step 2 ends after this many finger presses …
  int coverage_cells = 6;                      ///< … or when every cell of this many per side (on the sheet) has one
  double finger_radius_mm = 5;                 ///< written for a finger press (its size is not measured)
  std::vector<double> weights_N = {2.0, 5.0};  ///< step 3, in order (twin/calibration_person.hpp's defaults)
  double weight_radius_mm = 5;                 ///< each weight's flat foot
  PressSegmenterOptions segmenter;
  /// After the capture, calibrate (step 4); false: the capture alone (its files, for later).
  bool run_calibration = true;
  /// With no frame for this long, the source is taken as gone [s].
  double source_timeout_s = 10;
  void validate() const;  ///< \throw InvalidInput naming the option (core/option_check.hpp)
};

/// What the job tells the person: a step's instruction or result (a line of its own), and the
/// status of the step going on (the CLI rewrites one line in place on a terminal).
struct CaptureSay {
  std::function<void(const std::string& line)> line;
  std::function<void(const std::string& status)> status;
};

struct CaptureReport {
  std::string capture_dir, reference_path, frames_path, truth_path;
  double measured_noise_V = 0;  ///< a reading's, from step 1's frames
  double noise_V = 0;           ///< the segmenter's: the larger of that and the ADC model's
  int finger_presses = 0, weights = 0;
  /// Each finger press's place as the nominal fit saw it (the strongest contact; NaN: none fitted)
  std::vector<Vector2> placed_mm;
  int cells = 0, cells_covered = 0;            ///< the coverage map's cells on the sheet, and covered
  std::string coverage_map;                    ///< rows top (high y) first: '#' covered, '.' not, ' ' off the sheet
  bool stopped = false;                        ///< the stop flag ended it (Ctrl-C)
  std::string ended;                           ///< not empty: the source ended or failed early, why
  std::string offline_command;                 ///< how to run the calibration again from the files
  std::optional<CalibrateReport> calibration;  ///< when the capture completed
};

/// Captures, writes the files, and calibrates when the capture completes. `stop` (set by a
/// signal) ends it between frames, keeping what was captured. \throw InvalidInput (bad options, a
/// bad source spec, the sheet), IoError (a file), and what run_calibrate_job throws.
CaptureReport run_capture_job(const CaptureJob& job, const std::atomic<bool>& stop, const CaptureSay& say,
                              const Progress& progress = {});

}  // namespace emit
