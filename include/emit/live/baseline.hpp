#pragma once
/// \file baseline.hpp
/// The no-contact reference of a live stream (issue 6, item 4). It is captured as the mean of the
/// first `capture_frames` frames (and again on command: recapture()), then follows slow drift
/// (temperature, the sheet relaxing) as an exponential average, V_ref ← V_ref + rate·(V − V_ref),
/// only over frames in which nothing touches; while the sheet is touched it stays frozen, so a
/// press is never learnt as the baseline.
#include <cstdint>

#include "emit/core/types.hpp"

namespace emit {

struct BaselineOptions {
  int capture_frames = 10;  ///< frames averaged at start and on recapture()
  /// Weight of each untouched frame in the drift average: 0.01 follows drift with a time constant
  /// of ~100 frames (2 s at 50 frames/s), slow beside a finger landing.
  double drift_rate = 0.01;
};

class Baseline {
 public:
  /// \throw InvalidInput if capture_frames < 1 or drift_rate is not in [0, 1].
  explicit Baseline(BaselineOptions options = {});

  /// Start a fresh capture: the next capture_frames frames are averaged into a new reference.
  void recapture();
  /// While true, frames go to the capture and there is no reference to reconstruct against (the
  /// first one) or the old one stays in use (a recapture).
  bool capturing() const { return captured_ < options_.capture_frames; }
  /// Whether a reference exists (a first capture has completed).
  bool ready() const { return captures_ > 0; }
  /// Completed captures (1 after the first; +1 per recapture).
  std::uint64_t captures() const { return captures_; }

  /// Feed one capture frame (call while capturing()). Returns true when it completes the capture.
  /// \throw InvalidInput if its size differs from the frames before it.
  bool capture(const Frame& frame);
  /// Feed one frame reconstructed against the reference: an untouched one (`touched` false) moves
  /// the reference toward it by drift_rate; a touched one changes nothing. Returns whether the
  /// reference changed. \throw InvalidInput on a size mismatch.
  bool follow(const Frame& frame, bool touched);

  const Frame& reference() const { return reference_; }

 private:
  BaselineOptions options_;
  Frame sum_, reference_;
  int captured_ = 0;
  std::uint64_t captures_ = 0;
};

}  // namespace emit
