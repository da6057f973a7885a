#pragma once
/// \file sim_source.hpp
/// The digital twin as a live source: a scripted finger presses the sheet, the twin computes each
/// frame (with the ADC's noise) on a thread of its own, paced at SourceOptions::frames_per_s, and
/// the frames queue up for next() (the thread starts at the first call: the reader is ready). Which presses made frame
/// `sequence` is a pure function of the script (presses_of, twin/sim_script.hpp), so tests can compare contacts with
/// the truth.
///
/// The twin condenses each press onto a skeleton of its mesh (TwinOptions::condensed_frames): the
/// direct solve's frames to rounding, several times faster. At construction it times a few pressed
/// frames; if a frame takes more than 80 % of the asked interval, the source runs at the rate it
/// can keep (80 % of the thread's time, whole frames/s) and says so in description(). The script's
/// clock follows the rate it runs at, so the finger moves as fast in seconds either way.
#include <condition_variable>
#include <deque>
#include <exception>
#include <mutex>
#include <thread>

#include "emit/acquire/frame_source.hpp"
#include "emit/sensor/press.hpp"
#include "emit/twin/sim_script.hpp"
#include "emit/twin/twin.hpp"

namespace emit {

class SimSource : public FrameSource {
 public:
  /// Builds the twin (meshing takes a second); the frame thread starts at the first next().
  /// \throw InvalidInput for a bad script (e.g. a fixed press off the sheet: twin/sim_script.hpp)
  ///   or sensor.
  SimSource(const Sensor& sensor, SimScript script, const SourceOptions& options);
  ~SimSource() override;
  SimSource(const SimSource&) = delete;
  SimSource& operator=(const SimSource&) = delete;

  /// \throw IoError "source sim: …" once the twin has failed (after the frames it made before),
  ///   and again on every later call.
  bool next(SourceFrame& frame, std::chrono::milliseconds timeout) override;
  /// Never: the twin streams until it fails or the reader stops (frame_source.hpp).
  bool finished() const override;
  std::string description() const override;

  /// The presses the twin was given for frame `sequence` (empty: nothing touches).
  std::vector<Press> presses_of(std::uint64_t sequence) const;
  /// The pace it runs at [frames/s]: the asked one, or the one it can keep (0: unpaced).
  double frames_per_s() const { return frames_per_s_; }
  /// What a pressed frame took the twin when measured at construction [s].
  double measured_frame_s() const { return measured_frame_s_; }
  /// The mean time the twin has taken per frame since the source started [s] (0 before a frame).
  double frame_cost_s() const override;
  /// Frames the twin made that were dropped because the reader fell more than `queue_limit` behind
  /// (paced only, and from the script's first press on: unpaced, frames_per_s = 0, and for the
  /// untouched frames before it, from which the reference is captured, the twin waits for the
  /// reader and drops none, as a person waits for the program before pressing).
  std::uint64_t dropped() const;

  static constexpr std::size_t queue_limit = 8;

 private:
  void produce();
  /// Times a few pressed frames; lowers frames_per_s_ to what the twin can keep.
  void measure_pace();

  Sensor sensor_;
  SourceOptions options_;
  Twin twin_;
  ScriptedPresses script_;   ///< on twin_'s mesh
  double frames_per_s_ = 0;  ///< the pace it runs at
  double measured_frame_s_ = 0;
  double making_s_ = 0;  ///< the twin's time on the frames made so far (under mutex_)
  std::uint64_t made_ = 0;
  mutable std::mutex mutex_;
  std::condition_variable ready_;
  std::deque<SourceFrame> queue_;
  std::uint64_t dropped_ = 0;
  bool stop_ = false;
  std::exception_ptr failure_;
  std::thread thread_;
};

}  // namespace emit
