#pragma once
/// \file frame_source.hpp
/// Where live frames come from: the digital twin with a scripted or random finger now;
/// a recorded file and a serial port later. Every source hands out the same SourceFrame, so the
/// live loop (live/live_loop.hpp) does not care which one it reads.
#include <chrono>
#include <cstdint>
#include <string>

#include "emit/acquire/raw_frame.hpp"
#include "emit/core/types.hpp"
#include "emit/sensor/sensor.hpp"

namespace emit {

/// One frame as a source delivers it.
struct SourceFrame {
  Frame volts;                 ///< N×N [V], row = grounded electrode, column = sensed electrode
  std::uint64_t sequence = 0;  ///< as the source numbers frames (0, 1, 2, … for the simulator)
  double board_time_s = 0;     ///< when the board (or simulator) took it, on the board's clock
  /// When it reached the host: end-to-end latency is measured from here.
  std::chrono::steady_clock::time_point received;
  /// What the board sent (the twin: what its ADC read), as a recording keeps it (recorder.hpp).
  RawFrame raw;
};

struct SourceOptions {
  /// Pace of the simulator (and of a file replayed at its own pace) [frames/s]; 0: as fast as possible.
  double frames_per_s = 50;
  std::uint64_t seed = 1;  ///< the simulator's noise and random presses
  /// The simulator's first frames have no press, so the baseline (live/baseline.hpp) captures an
  /// untouched sheet; the scripts start after them.
  int untouched_frames = 15;
  /// A recording (file:) starts again after its last frame, its numbers going on (file_source.hpp).
  bool loop = false;
  void validate() const;  ///< \throw InvalidInput naming the option (core/option_check.hpp)
};

class FrameSource {
 public:
  virtual ~FrameSource() = default;
  /// Waits up to `timeout` for the next frame. true: `frame` filled. false: none yet (the caller
  /// serves commands and asks again).
  /// \throw IoError when the source has failed for good or ended (finished() is then true).
  virtual bool next(SourceFrame& frame, std::chrono::milliseconds timeout) = 0;
  virtual bool finished() const = 0;
  /// One line for people, e.g. "sim: scripted finger on default 60 mm", "serial:/dev/ttyUSB0 at 921600".
  virtual std::string description() const = 0;
  /// The mean time the source has spent making a frame on a thread of its own [s] (the simulator's
  /// twin); 0 for a source that only reads what a board or a file gives.
  virtual double frame_cost_s() const { return 0; }
};

}  // namespace emit
