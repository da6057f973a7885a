#pragma once
/// \file calibration_person.hpp
/// A scripted person calibrating a sheet without a robot (issue 33), for the twin to stand in for
/// the board: `emit simulate --script calibration` and the live source `sim:calibration`. The person
/// lifts everything for `quiet_s` (the reference's quiet frames), then presses one finger at a time
/// at random places that cover the sheet (held 0.4–0.6 s, lifted 0.3 s between, a force drawn in
/// [min_force_N, max_force_N]), then puts down each known weight in turn (a flat disc of
/// `weight_radius_mm`, somewhere on the sheet), lifting between. A pure function of the sheet, the
/// options and the seed, so that the truth it writes (places and forces known) checks a capture
/// (jobs/capture_job.hpp) that was not told them.
#include <cstdint>
#include <vector>

#include "emit/sensor/press.hpp"
#include "emit/sensor/sensor.hpp"

namespace emit {

/// The known weights a person puts down by default [N], here and in `emit calibrate --capture`
/// (`--weights-N`): two kitchen weights of about 200 g and 500 g.
inline const std::vector<double> default_calibration_weights_N = {2.0, 5.0};

struct CalibrationPersonOptions {
  int presses = 60;                                               ///< finger presses, one at a time
  double quiet_s = 1.0;                                           ///< everything lifted at the start [s]
  double min_hold_s = 0.4, max_hold_s = 0.6;                      ///< each press held for a time drawn between them [s]
  double lift_s = 0.3;                                            ///< lifted between presses [s]
  double min_force_N = 2, max_force_N = 39;                       ///< a finger press's force, drawn uniformly
  double radius_mm = 5;                                           ///< the finger's contact radius
  std::vector<double> weights_N = default_calibration_weights_N;  ///< put down after the finger presses
  double weight_radius_mm = 5;                                    ///< each weight's flat foot
  /// Every centre keeps its radius and this much more from the border (all of its disc on the sheet).
  double margin_mm = 3;
  std::uint64_t seed = 1;  ///< the places, forces and hold times
  void validate() const;   ///< \throw InvalidInput naming the option (core/option_check.hpp)
};

/// One press of the person: pressed from start_s (inclusive) to end_s (exclusive).
struct PersonPress {
  double start_s = 0, end_s = 0;
  Press press;
  bool weight = false;  ///< a known weight (else a finger)
};

class CalibrationPerson {
 public:
  /// Draws the whole session. \throw InvalidInput for bad options or a sheet without room for a
  /// press `radius + margin` from its border.
  CalibrationPerson(const Sensor& sensor, const CalibrationPersonOptions& options);

  /// The presses in time order: the finger presses, then the weights.
  const std::vector<PersonPress>& presses() const { return presses_; }
  /// The press at time t_s since the session began, or nullptr (lifted).
  const Press* press_at(double t_s) const;
  /// The session's length: the last press's end and a lift after it [s].
  double duration_s() const { return duration_s_; }
  /// The session sampled at `frames_per_s` (frame k at k / frames_per_s), one entry per frame:
  /// the truth of `emit simulate --script calibration`.
  PressSequence frames(double frames_per_s) const;

 private:
  std::vector<PersonPress> presses_;
  double duration_s_ = 0;
};

}  // namespace emit
