#pragma once
/// \file reference.hpp
/// The no-contact reference V_ref, against which every frame's change δV = V − V_ref is taken
/// (docs/physics.md, "Reference and noise"), in one place for files, Python and live streams:
/// - `Reference`: the frame and how many frames' noise it holds. Its noise adds to every δV, so
///   the significance floor needs the count (model/image_noise.hpp: σ·√(1 + 1/n)).
/// - `average_reference`: a robust mean of untouched frames (a reference file, a stack of frames).
/// - `ReferenceTracker`: a stream's reference: captured as that mean of its first frames (and
///   again on command), then following slow drift (temperature, the sheet relaxing) over frames in
///   which nothing touches, the count following the average's noise.
#include <cstdint>
#include <vector>

#include "emit/core/types.hpp"

namespace emit {

struct Reference {
  Frame frame;  ///< N×N volts, the layout of a frame (core/types.hpp)
  /// The number of independent frames whose noise it holds: its noise variance is σ²/frames (a
  /// mean of n frames: n; an exponential average: more, see ReferenceTracker).
  double frames = 1;
};

/// The mean of `frames`, robust to a bad one: frames whose RMS distance from the per-reading
/// median exceeds 3× the median of those distances (a glitch, a touch, a burst of noise) are left
/// out; with one or two frames, the plain mean. `frames` is the count kept. Values that are not
/// finite (a board's dropped reading, a file's `nan`) are left out of their reading's mean; a
/// reading with none is NaN (the reconstructor masks it in every frame).
/// \throw InvalidInput if there are none or their sizes differ.
Reference average_reference(const std::vector<Frame>& frames);

struct ReferenceOptions {
  int capture_frames = 10;  ///< frames averaged at start and on recapture()
  /// Weight of each untouched frame in the drift average, V_ref ← V_ref + rate·(V − V_ref): 0.01
  /// follows drift with a time constant of ~100 frames (2 s at 50 frames/s), slow beside a finger
  /// landing. 0: the captured reference stays.
  double drift_rate = 0.01;
  void validate() const;  ///< \throw InvalidInput naming the option
};

/// A stream's reference. While the sheet is touched it stays frozen, so a press is never learnt
/// as the reference. The capture buffers its frames (allocated by the first capture, reused).
class ReferenceTracker {
 public:
  /// \throw InvalidInput as ReferenceOptions::validate.
  explicit ReferenceTracker(ReferenceOptions options = {});

  /// Start a fresh capture: the next capture_frames frames are averaged into a new reference.
  void recapture();
  /// While true, frames go to the capture and there is no reference to reconstruct against (the
  /// first one) or the old one stays in use (a recapture).
  bool capturing() const { return captured_ < options_.capture_frames; }
  /// Whether a reference exists (a first capture has completed).
  bool ready() const { return captures_ > 0; }
  /// Completed captures (1 after the first; +1 per recapture).
  std::uint64_t captures() const { return captures_; }

  /// Feed one capture frame (call while capturing()). Returns true when it completes the capture
  /// (the reference is then average_reference of the captured frames).
  /// \throw InvalidInput if its size differs from the frames before it.
  bool capture(const Frame& frame);
  /// Feed one frame reconstructed against the reference: an untouched one (`touched` false) moves
  /// the reference toward it by drift_rate, and its count to that of the average (variance
  /// (1 − r)²/n + r² frames' worth); a touched one changes nothing. Returns whether the reference
  /// changed. \throw InvalidInput if there is no reference yet or on a size mismatch.
  bool follow(const Frame& frame, bool touched);

  const Reference& reference() const { return reference_; }

 private:
  ReferenceOptions options_;
  std::vector<Frame> captured_frames_;
  Reference reference_;
  int captured_ = 0;
  std::uint64_t captures_ = 0;
};

}  // namespace emit
