#pragma once
/// \file contact_tracker.hpp
/// Touches over time: gives each frame's contacts an id that lasts while the touch does, a phase
/// (down, move; up reported once after the last frame, with the touch's last state), a velocity,
/// and optionally a filtered position. A robot or an interface consumes touches, not frames.
///
/// The rule (docs/physics.md, "Touch over time"), per frame at time t:
///  1. Each live touch is predicted to t at constant velocity (its filter's, or the finite
///     difference of its last two places), and its force at its last rate of change.
///  2. Touches and contacts are paired by the least total cost (optimal_assignment.hpp), a pair's
///     cost (d/gate)² + force_weight·(ΔF / max(F̂, F))², d the contact's distance from the
///     touch's predicted place along the sheet's chart (sensor/surface.hpp); a pair farther than
///     gate_mm cannot be made. Leaving a touch unpaired costs more than any pair (2 + 2·force_weight),
///     so as many pairs are made as the gate allows.
///  3. A paired contact takes its touch's id (phase move). A contact left over is a new touch
///     (phase down) with the next id; ids are never reused. A touch left over coasts (predicted on,
///     not reported) for up to coast_frames frames, and then ends: reported once in ended() with
///     its last state and phase up.
///  4. Merges (two touches, one contact) and splits (one touch, two contacts) follow: the contact
///     keeps the touch it pairs with at least cost; the other touch coasts and ends unless it is
///     seen again within coast_frames, the other contact is a new touch.
///  5. With `filter`, each touch's place is a constant-velocity Kalman filter's (per chart axis),
///     its measurement noise the contact's own 1σ (x_std_mm, y_std_mm) where given, else
///     measurement_std_mm. A contact farther from the prediction than jump_sigmas of the
///     prediction's spread is a jump (a press that moved at once, a finger that started): the
///     filter restarts there, so it does not lag a real press.
///
/// Per frame, update() allocates nothing: tracks and scratch are sized at construction for
/// `max_contacts`.
#include <cstdint>
#include <vector>

#include "emit/frame/contacts.hpp"
#include "emit/frame/optimal_assignment.hpp"

namespace emit {

struct TrackerOptions {
  /// A contact farther than this from a track's predicted place [mm] is not that touch.
  double gate_mm = 15;
  /// Frames a track may go unseen before its touch is reported up (a fit that misses one frame
  /// does not end a touch); 0: up at the first frame without it.
  int coast_frames = 1;
  /// Smooth each touch's position (a constant-velocity Kalman filter); false: the contacts' own.
  bool filter = false;
  /// The weight of the force's relative change in a pair's cost (0: position alone).
  double force_weight = 0.25;
  /// The filter's measurement noise [mm] (1σ per axis) for contacts that give none.
  double measurement_std_mm = 0.1;
  /// The filter's process noise: a touch's random acceleration, 1σ [mm/s²]. Smaller smooths more
  /// and follows a finger that speeds up or slows down later (a jump restarts it: jump_sigmas).
  double acceleration_std_mm_per_s2 = 100;
  /// A contact this many σ of the prediction's spread (its innovation's) from it restarts the filter.
  double jump_sigmas = 4;
  void validate() const;  ///< \throw InvalidInput naming the option (core/option_check.hpp)
};

class ContactTracker {
 public:
  /// \param max_contacts  the most contacts a frame may hold (the reconstructor's limit): a
  ///                      frame's contacts past it are passed on untracked (id −1, phase none).
  /// \param surface       the sheet's shape: distances and velocities are along its chart
  ///                      (sensor/surface.hpp; around a sleeve's seam too); the default, a flat sheet.
  /// \throw InvalidInput for a bad option or max_contacts < 1.
  explicit ContactTracker(const TrackerOptions& options = {}, int max_contacts = 64, Shape surface = {});

  /// This frame's contacts, tracked: each a copy of a contact of `contacts` (in the same order) with
  /// its id, phase and velocity set (and its position filtered when asked). `time_s` is the frame's
  /// time (the board's clock), increasing; a time behind the last one (a source that started
  /// again) ends every touch first, as reset() does. Valid until the next call.
  /// \throw InvalidInput for a time that is not finite.
  const std::vector<Contact>& update(const std::vector<Contact>& contacts, double time_s);
  /// The touches that ended at the last update(): each its last state, with phase up. Valid until
  /// the next call.
  const std::vector<Contact>& ended() const { return ended_; }
  /// Forget every touch (e.g. the reference was captured again); ids go on from where they were.
  /// The touches alive end at the next update(): reported in its ended(), matched to no contact.
  void reset();

  const TrackerOptions& options() const { return options_; }
  /// Touches alive (seen or coasting).
  int live_count() const;
  /// The next new touch's id (ids so far: 0 up to it).
  std::int64_t next_id() const { return next_id_; }

 private:
  /// Along one chart axis: the Kalman filter's state (place, velocity) and covariance.
  struct Axis {
    double p = 0, v = 0, ppp = 0, ppv = 0, pvv = 0;
  };
  struct Track {
    bool live = false;
    std::int64_t id = -1;
    int missed = 0;     ///< frames unseen in a row
    double time_s = 0;  ///< of its last update (seen or coasted)
    Axis axis[2];       ///< chart place and velocity (filtered, or measured and differenced)
    double force_N = 0, force_rate_N_per_s = 0;
    double predicted[2] = {0, 0}, predicted_force_N = 0;  ///< at this frame's time
    Contact last;                                         ///< as last reported
  };

  Vector2 chart_difference(const Vector2& a,
                           const Vector2& b) const;  ///< a − b (across a sleeve's seam: the shorter way)
  void predict(Track& track, double time_s) const;
  void start(Track& track, const Contact& contact, const Vector2& chart, double time_s, Contact& out);
  void follow(Track& track, const Contact& contact, const Vector2& chart, double time_s, Contact& out) const;
  void end(Track& track);
  void end_all();

  TrackerOptions options_;
  Shape surface_;
  double sleeve_period_mm_ = 0;  ///< 2πR around a sleeve, else 0
  std::vector<Track> tracks_;    ///< 2 × max_contacts slots, live or free
  std::vector<int> rows_;        ///< the live tracks' slots, this frame
  std::vector<Vector2> charts_;  ///< this frame's contacts' chart points
  std::vector<double> cost_;
  std::vector<char> paired_;  ///< per contact
  OptimalAssignment assignment_;
  std::vector<Contact> tracked_, ended_;
  std::int64_t next_id_ = 0;
  double last_time_s_ = 0;
  int max_contacts_;
  bool started_ = false, reset_pending_ = false;
};

}  // namespace emit
