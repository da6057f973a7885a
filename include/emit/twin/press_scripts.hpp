#pragma once
/// \file press_scripts.hpp
/// Sequences of presses for the twin: a grid of single presses, random presses, two-, three- and
/// four-finger presses, a press that moves over time, and two fingers that cross. Every press lies inside the sheet, at
/// least `margin_mm` from its border.
#include <cstdint>
#include <string>

#include "emit/sensor/press.hpp"
#include "emit/sensor/sensor.hpp"
#include "emit/twin/calibration_person.hpp"

namespace emit {

struct PressStyle {
  double radius_mm = 5.0;
  double min_force_N = 10.0;  ///< forces are drawn uniformly from [min_force_N, max_force_N]
  double max_force_N = 10.0;
  double margin_mm = 5.0;  ///< smallest distance from a press centre to the border
  std::uint64_t seed = 1;
  PressProfile profile = PressProfile::flat;  ///< the indenters' profile
};

/// One press per frame on a square grid of pitch spacing_mm, each moved by up to ±jitter_mm.
/// \throw InvalidInput for a spacing that is not positive, or so small that the grid's nodes
/// overflow an int.
PressSequence grid_script(const Sensor& sensor, double spacing_mm, double jitter_mm, const PressStyle& style);
/// One press per frame at a uniformly random place.
PressSequence random_script(const Sensor& sensor, int frames, const PressStyle& style);
/// Two simultaneous presses per frame, their centres min..max_separation_mm apart.
PressSequence two_finger_script(const Sensor& sensor, int frames, double min_separation_mm, double max_separation_mm,
                                const PressStyle& style);
/// `fingers` simultaneous presses per frame at random places, every two at least
/// min_separation_mm apart. \throw InvalidInput when they do not fit on the sheet.
PressSequence fingers_script(const Sensor& sensor, int frames, int fingers, double min_separation_mm,
                             const PressStyle& style);
/// One press moving in a straight line from `from` to `to` over `frames` frames.
PressSequence moving_script(const Sensor& sensor, int frames, const Vector2& from_mm, const Vector2& to_mm,
                            const PressStyle& style);
/// Two fingers passing each other, their forces crossing (contact tracking's test,
/// frame/contact_tracker.hpp): each moves along a straight line at its own constant speed, the two
/// lines parallel and `separation` apart, past each other half-way through (frame (frames − 1)/2);
/// the first finger's force rises linearly from F_low to F_high while the second's falls from F_high
/// to F_low, so that they are equal there too. Drawn from style.seed: the crossing's place and the
/// lines' angle, each path's length (10-40 mm over the frames), F_low < F_high within
/// [min_force_N, max_force_N], and the separation within [min_separation_mm, max_separation_mm].
/// Each frame holds {first finger, second finger}, in that order (the truth of their identities).
/// 	hrow InvalidInput for fewer than 2 frames, separations not 0 < min ≤ max, or a sheet without room.
PressSequence crossing_script(const Sensor& sensor, int frames, double min_separation_mm, double max_separation_mm,
                              const PressStyle& style);

/// A script by name, as `emit simulate --script` takes it, with every script's parameters.
struct PressScript {
  enum class Kind { none, grid, random, two_finger, three_finger, four_finger, moving, crossing, calibration };
  Kind kind = Kind::none;
  int frames = 20;                        ///< none (no-contact references), random, two_finger, moving, crossing
  double spacing_mm = 10, jitter_mm = 0;  ///< grid
  /// two_finger, crossing (at the closest approach); three/four: min only
  double min_separation_mm = 12, max_separation_mm = 40;
  Vector2 from_mm{0, 0}, to_mm{0, 0};  ///< moving
  /// calibration: a person calibrating without a robot (twin/calibration_person.hpp), sampled at
  /// frames_per_s (its frames are 1/frames_per_s apart in its time)
  CalibrationPersonOptions person;
  double frames_per_s = 50;
  PressStyle style;
};

/// "none", "grid", "random", "two-finger", "three-finger", "four-finger", "moving", "crossing",
/// "calibration". \throw
/// InvalidInput naming the text.
PressScript::Kind parse_script_kind(const std::string& name);

/// How many frames run_script gives, at most, found without running it: `frames`, or a grid's
/// nodes over the sheet's bounding box (those outside the margin are dropped after), a
/// calibration person's session at its frames_per_s; 0 for a
/// spacing that is not positive (grid_script refuses it).
double script_frame_count(const Sensor& sensor, const PressScript& script);

/// The script's presses, frame by frame (`none`: `frames` frames with no press).
PressSequence run_script(const Sensor& sensor, const PressScript& script);

}  // namespace emit
