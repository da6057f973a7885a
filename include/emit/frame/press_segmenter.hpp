#pragma once
/// \file press_segmenter.hpp
/// Stable presses found in a stream of frames, for a calibration captured by hand (issue 33: a
/// person presses anywhere, one finger at a time; jobs/capture_job.hpp). A frame is *pressed* when
/// its change from the reference, the rms over the N(N − 1) readings of V − V_ref, is well above
/// the noise that change has untouched; *lifted* when back near it. A press is the longest *stable*
/// run of pressed frames between two lifts: each frame's change from the one before is small beside
/// the press's own change (a finger settled, not landing, rolling or lifting), at least min_frames
/// long. Its frame is the mean of the run's middle (trim_frames left out at either end), found at
/// the lift that ends the touch, so one touch gives at most one press.
///
/// The thresholds are in units of the noise (docs/physics.md, "Reference and noise"): a reading's
/// noise σ (sensor/adc.hpp's reading_noise_V, or measured_reading_noise_V of quiet frames if larger:
/// an untouched sheet reads 0 V, where the ADC clips half the noise away, 0.58 σ left) and the
/// reference's of n frames make an untouched frame's change σ_u = σ·√(1 + 1/n) per reading; its
/// rms over M = N(N − 1) readings is σ_u within a relative 1/√(2M) (≤ 20 % for N ≥ 4: 12 readings).
/// A frame is lifted below lift_factor·σ_u (3: ten of those deviations above an untouched frame,
/// even at N = 4), pressed above press_factor·σ_u (8); between the two a touch goes on (hysteresis,
/// a finger lifting slowly is not two touches). Two frames of a press held still differ by noise
/// alone, rms √2·σ; stable means within stable_noise_factor of that plus stable_fraction of the
/// press's change (a real finger's slow creep). The twin's 2 N press on the 60 mm sheet changes the
/// frame by ~100 mV rms, against σ_u ≈ 0.6 mV.
///
/// Per frame: no allocation after construction (its buffers are the frame's size).
#include <cstdint>
#include <vector>

#include "emit/core/types.hpp"
#include "emit/frame/reference.hpp"

namespace emit {

struct PressSegmenterOptions {
  double press_factor = 8;  ///< pressed: rms change > this × σ_u
  double lift_factor = 3;   ///< lifted: rms change < this × σ_u
  /// stable: rms change from the previous frame < stable_noise_factor·√2·σ + stable_fraction·(its rms change)
  double stable_noise_factor = 4;
  double stable_fraction = 0.05;
  int min_frames = 5;     ///< a stable run at least this long is a press (0.1 s at 50 frames/s)
  int trim_frames = 1;    ///< left out of the mean at either end of the run (the finger settling, leaving)
  void validate() const;  ///< \throw InvalidInput naming the option (core/option_check.hpp)
};

/// A press found: the mean frame of its stable run's middle.
struct SegmentedPress {
  Frame frame;  ///< N×N volts: the mean of the run's frames less trim_frames at either end
  std::uint64_t first_frame = 0, last_frame = 0;  ///< the stable run, numbered as pushed (0 first)
  int frames_averaged = 0;
  double change_rms_V = 0;  ///< the mean's rms change from the reference
};

class PressSegmenter {
 public:
  /// `reading_noise_V`: a reading's noise σ (> 0). \throw InvalidInput for a reference that is not
  /// square with 2 or more electrodes, a noise that is not positive, or bad options.
  PressSegmenter(const Reference& reference, double reading_noise_V, PressSegmenterOptions options = {});

  /// Feeds the next frame (the reference's size). true: a touch has just ended (this frame is
  /// lifted) with a stable run in it; press() holds it until the next true. \throw InvalidInput on
  /// a size mismatch.
  bool push(const FrameView& frame);
  bool push(const Frame& frame) { return push(frame_view(frame)); }
  const SegmentedPress& press() const { return press_; }

  /// Whether the last frame was within a touch (not yet lifted).
  bool touched() const { return touched_; }
  /// The last frame's rms change from the reference [V].
  double change_rms_V() const { return change_rms_V_; }
  /// The longest stable run in the touch going on so far (frames), for a status line.
  int stable_frames() const { return std::max(run_, best_run_); }
  /// σ_u, the rms change of an untouched frame [V], and the thresholds it makes.
  double untouched_noise_V() const { return untouched_noise_V_; }
  double press_threshold_V() const { return options_.press_factor * untouched_noise_V_; }
  double lift_threshold_V() const { return options_.lift_factor * untouched_noise_V_; }
  std::uint64_t frames_seen() const { return frames_seen_; }

 private:
  /// rms over the off-diagonal readings of a − b.
  double rms_difference(const FrameView& a, const FrameView& b) const;
  void end_run();

  PressSegmenterOptions options_;
  Frame reference_;
  double noise_V_, untouched_noise_V_;
  Frame previous_, sum_, best_sum_;
  std::vector<Frame> delayed_;  ///< the run's last trim_frames frames, a ring, not yet in sum_
  int run_ = 0, best_run_ = 0;  ///< frames in the current stable run; in the best of this touch
  std::uint64_t run_first_ = 0, best_first_ = 0, frames_seen_ = 0;
  bool touched_ = false, have_previous_ = false;
  double change_rms_V_ = 0;
  SegmentedPress press_;
};

/// A reading's noise σ measured from frames in which nothing touches: the rms of their
/// off-diagonal readings' deviations from those readings' means, with K − 1 degrees of freedom
/// for K frames. \throw InvalidInput for fewer than 2 frames or frames of different sizes.
double measured_reading_noise_V(const std::vector<Frame>& quiet_frames);

}  // namespace emit
