#pragma once
/// \file contact_tracker.hpp
/// Touches over time: gives each frame's contacts an id that lasts while the touch does, a phase
/// (down, move; up reported once after the last frame, with the touch's last state), a velocity,
/// and optionally a filtered position. A robot or an interface consumes touches, not frames.
///
/// Per frame, update() allocates nothing: tracks and scratch are sized at construction for
/// `max_contacts`. The rule it follows (assignment, gating, merges and splits, filtering) is
/// documented in docs/physics.md, "Touch over time".
#include <cstdint>
#include <vector>

#include "emit/frame/contacts.hpp"

namespace emit {

struct TrackerOptions {
  /// A contact farther than this from a track's predicted place [mm] is not that touch.
  double gate_mm = 15;
  /// Frames a track may go unseen before its touch is reported up (a fit that misses one frame
  /// does not end a touch); 0: up at the first frame without it.
  int coast_frames = 1;
  /// Smooth each touch's position (a constant-velocity Kalman filter); false: the contacts' own.
  bool filter = false;
  void validate() const;  ///< \throw InvalidInput naming the option (core/option_check.hpp)
};

class ContactTracker {
 public:
  /// \param max_contacts  the most contacts a frame may hold (the reconstructor's limit).
  explicit ContactTracker(const TrackerOptions& options = {}, int max_contacts = 64);

  /// This frame's contacts, tracked: each a copy of a contact of `contacts` (in the same order) with
  /// its id, phase and velocity set (and its position filtered when asked). `time_s` is the frame's
  /// time (the board's clock), increasing. Valid until the next call.
  const std::vector<Contact>& update(const std::vector<Contact>& contacts, double time_s);
  /// The touches that ended at the last update(): each its last state, with phase up. Valid until
  /// the next call.
  const std::vector<Contact>& ended() const { return ended_; }
  /// Forget every touch (e.g. the reference was captured again); ids go on from where they were.
  void reset();

 private:
  TrackerOptions options_;
  std::vector<Contact> tracked_, ended_;
};

}  // namespace emit
