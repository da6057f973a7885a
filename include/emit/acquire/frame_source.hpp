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
  /// A serial port that went away (a pulled cable) is reopened every 0.5 s for this long [s]; if
  /// it is not back by then, the source fails with the port's last error (serial_source.hpp).
  double reconnect_s = 30;
  void validate() const;  ///< \throw InvalidInput naming the option (core/option_check.hpp)
};

class FrameSource {
 public:
  virtual ~FrameSource() = default;
  /// Waits up to `timeout` for the next frame. true: `frame` filled. false: none yet (the caller
  /// serves commands and asks again; a source that can recover, a serial port whose cable was
  /// pulled, is retrying meanwhile).
  /// \throw IoError naming the source and why when it has failed for good (a corrupt recording, a
  ///   port gone past its reconnection time, the simulator's error): every later call throws it
  ///   again, and finished() stays false. Also when asked for more after it finished.
  virtual bool next(SourceFrame& frame, std::chrono::milliseconds timeout) = 0;
  /// The source ended as it should (a recording's last frame was handed out): no frame will come,
  /// and nothing went wrong. A failed source is not finished: its failure is next()'s to throw,
  /// so a reader that stops on finished() never takes a failure for an end (live/live_loop.hpp).
  virtual bool finished() const = 0;
  /// One line for people, e.g. "sim: scripted finger on default 60 mm", "serial:/dev/ttyUSB0 at 921600".
  virtual std::string description() const = 0;
  /// The mean time the source has spent making a frame on a thread of its own [s] (the simulator's
  /// twin); 0 for a source that only reads what a board or a file gives.
  virtual double frame_cost_s() const { return 0; }
};

}  // namespace emit
