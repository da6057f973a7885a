#pragma once
/// \file reading_screen.hpp
/// Which readings of a real board's frames can be trusted. A board drops samples (a 0, or a value
/// not finite), clips at its rail (the ADC's top code, repeated), and loses channels (a wire off:
/// the same value in every frame, or garbage in most). A reading that cannot be trusted is left
/// out of its frame's fit (masked: frame/press_locator.hpp marginalises it, the press response's
/// fit fills it from the model at the press's place); a channel bad in most frames, or stuck, is
/// dropped for good: it reads as no change in every frame.
#include <limits>
#include <string>
#include <vector>

#include "emit/core/types.hpp"

namespace emit {

struct ReadingScreen {
  /// A reading at or above this is clipped (the board's rail); +∞: no rail.
  double rail = std::numeric_limits<double>::infinity();
  /// dropped[m]: channel m is left out of every frame (empty: none is).
  std::vector<char> dropped;

  bool is_dropped(Index m) const { return !dropped.empty() && dropped[static_cast<std::size_t>(m)] != 0; }
  /// Whether a reading and its reference can be used: both positive and below the rail (so
  /// finite: NaN compares false, +∞ is never below it).
  bool usable(double value, double reference) const {
    return value > 0 && reference > 0 && value < rail && reference < rail;
  }
};

struct ReadingSurveyOptions {
  /// A stated rail (the board's ADC range); NaN: found from the data, as the largest value when
  /// it recurs in at least `rail_frames` of the frames (a clipping ADC repeats its top code;
  /// a free reading at full resolution rarely repeats the largest value at all).
  double rail = std::numeric_limits<double>::quiet_NaN();
  double rail_frames = 0.01;
  /// A channel bad in more than this fraction of the frames is dropped for good.
  double drop_above = 0.5;

  /// \throw InvalidInput naming the option.
  void validate() const;
};

/// What a survey of a data set's frames found.
struct ReadingSurvey {
  ReadingScreen screen;
  bool rail_found = false;        ///< the rail came from the data (not stated)
  std::vector<Index> bad_frames;  ///< per channel: the frames where it could not be used
  std::vector<Index> stuck;       ///< channels with one value in every frame and reference
  Index frames_with_bad = 0;      ///< frames with a reading masked (dropped channels aside)
  Index masked_readings = 0;      ///< readings masked in all (dropped channels aside)

  /// The channels dropped for good, in order.
  std::vector<Index> dropped() const;
  /// The channels with the most bad frames (most first, at most `count`, none with 0).
  std::vector<Index> worst(std::size_t count) const;
};

/// Surveys frames and references (presses × M each, row i's reference for frame i).
/// \throw InvalidInput for different shapes, or as options.validate().
ReadingSurvey survey_readings(const Matrix& frames, const Matrix& references, const ReadingSurveyOptions& options = {});

}  // namespace emit
