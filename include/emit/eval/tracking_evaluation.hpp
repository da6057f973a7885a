#pragma once
/// \file tracking_evaluation.hpp
/// `emit eval --tracking`: touches over time on the twin (frame/contact_tracker.hpp), on a mesh of
/// another seed than the reconstruction's, with contact fitting as `emit live` runs it (each frame
/// seeded by the last):
///
/// 1. crossings: two fingers passing each other, their forces crossing (twin/press_scripts.hpp's
///    crossing_script), each trial drawn from its own seed (place, angle, speeds, forces, the
///    separation at the closest approach, 20-40 frames); tracked with the filter off and on.
///    A trial swaps when a finger is reported under the other's id; it breaks when a finger's id
///    changes otherwise (lost and found again as a new touch). Each trial also counts its downs
///    and ups (two of each when nothing breaks).
/// 2. a press held still (5 N): the position's jitter (rms about its mean) unfiltered and filtered.
/// 3. steps: the press moves at once by 0.5 and 3 mm; the lag is the frames after the step's own
///    until the filtered position is first within 10 % of the step of the new place (0: in the
///    step's frame), the new place the unfiltered contacts' mean after the step.
#include <cstdint>
#include <vector>

#include "emit/core/progress.hpp"
#include "emit/eval/sheet_evaluation.hpp"
#include "emit/frame/contact_tracker.hpp"

namespace emit {

struct TrackingEvalOptions {
  int mesh_seed = 3;        ///< the twin's mesh (another than the reconstruction's)
  std::uint64_t seed = 31;  ///< the noise; crossing k is drawn from seed + 1 + k
  int crossings = 200;
  int min_frames = 20, max_frames = 40;  ///< each crossing's, drawn
  double min_separation_mm = 12, max_separation_mm = 20;
  double min_force_N = 2, max_force_N = 12;
  double frames_per_s = 50;  ///< the frames' times (the board's clock)
  int still_frames = 150;    ///< of the press held still (and each side of a step)
  double still_force_N = 5;
  TrackerOptions tracker;  ///< its `filter` is set off and on in turn
  void validate() const;   ///< \throw InvalidInput naming the option
};

/// A smoke test (`--quick`): 4 crossings, 40 frames held still.
TrackingEvalOptions quick_tracking_options();

struct CrossingScore {
  int trials = 0;
  int swapped = 0;       ///< trials where a finger took the other's id
  int broken = 0;        ///< trials where a finger's id changed otherwise
  int right_events = 0;  ///< trials with exactly two downs and two ups
  double swap_free() const { return trials > 0 ? 1 - static_cast<double>(swapped) / trials : 0; }
};

struct StepLag {
  double step_mm = 0;
  int lag_frames = 0;  ///< filtered; −1: not within 10 % by the run's end
  int raw_lag_frames = 0;
};

struct TrackingEvaluation {
  CrossingScore unfiltered, filtered;
  int frames_missing_a_finger = 0;  ///< crossing frames where a finger had no contact within 5 mm
  int crossing_frames = 0;
  double jitter_mm = 0, filtered_jitter_mm = 0;  ///< the still press's, rms about the mean (both axes)
  std::vector<StepLag> steps;
  double reconstruct_ms_per_frame = 0, track_us_per_frame = 0;
};

/// The round on `eval_case`'s sheet. \throw InvalidInput (bad options, a sheet without room).
TrackingEvaluation evaluate_tracking(const EvalCase& eval_case, const TrackingEvalOptions& options,
                                     const Progress& progress = {});

}  // namespace emit
