#include "emit/frame/contact_tracker.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>
#include <utility>

#include "emit/core/errors.hpp"
#include "emit/core/option_check.hpp"
#include "emit/sensor/surface.hpp"

namespace emit {

namespace {

/// A new or restarted touch's velocity spread [mm/s]: about a fast finger's, so that the next
/// frame's place sets its velocity (two-point start).
constexpr double start_velocity_std_mm_per_s = 300;
/// Forces below this [N] count as this in the relative force change (a contact of no force).
constexpr double force_floor_N = 0.05;

}  // namespace

void TrackerOptions::validate() const {
  option_check::positive("TrackerOptions", "gate_mm", gate_mm);
  option_check::at_least("TrackerOptions", "coast_frames", coast_frames, 0);
  option_check::non_negative("TrackerOptions", "force_weight", force_weight);
  option_check::positive("TrackerOptions", "measurement_std_mm", measurement_std_mm);
  option_check::positive("TrackerOptions", "acceleration_std_mm_per_s2", acceleration_std_mm_per_s2);
  option_check::positive("TrackerOptions", "jump_sigmas", jump_sigmas);
}

ContactTracker::ContactTracker(const TrackerOptions& options, int max_contacts, Shape surface)
    : options_((options.validate(), options)), surface_(std::move(surface)), max_contacts_(max_contacts) {
  if (max_contacts < 1)
    throw InvalidInput("ContactTracker: max_contacts must be at least 1, got " + std::to_string(max_contacts));
  if (is_sleeve(surface_)) sleeve_period_mm_ = 2 * std::numbers::pi * surface_.radius_mm;
  // A frame's contacts all new while as many touches coast: 2 × max_contacts touches at once.
  // More coasting ones (coast_frames > 1 and every contact new, frame after frame) take the slots
  // of those unseen longest, which end early.
  const auto slots = 2 * static_cast<std::size_t>(max_contacts);
  tracks_.resize(slots);
  rows_.reserve(slots);
  charts_.resize(static_cast<std::size_t>(max_contacts));
  paired_.resize(static_cast<std::size_t>(max_contacts));
  cost_.resize(slots * (slots + static_cast<std::size_t>(max_contacts)));
  assignment_.reserve(static_cast<int>(slots), static_cast<int>(slots) + max_contacts);
  tracked_.reserve(static_cast<std::size_t>(max_contacts));
  ended_.reserve(slots);
}

int ContactTracker::live_count() const {
  return static_cast<int>(std::count_if(tracks_.begin(), tracks_.end(), [](const Track& t) { return t.live; }));
}

void ContactTracker::reset() { reset_pending_ = true; }

Vector2 ContactTracker::chart_difference(const Vector2& a, const Vector2& b) const {
  Vector2 d = a - b;
  if (sleeve_period_mm_ > 0) d.y() -= sleeve_period_mm_ * std::round(d.y() / sleeve_period_mm_);
  return d;
}

void ContactTracker::predict(Track& track, double time_s) const {
  const double dt = std::max(0.0, time_s - track.time_s);
  for (int k = 0; k < 2; ++k) track.predicted[k] = track.axis[k].p + track.axis[k].v * dt;
  track.predicted_force_N = std::max(0.0, track.force_N + track.force_rate_N_per_s * dt);
}

void ContactTracker::start(Track& track, const Contact& contact, const Vector2& chart, double time_s, Contact& out) {
  track.live = true;
  track.id = next_id_++;
  track.missed = 0;
  track.time_s = time_s;
  const double std_mm[2] = {contact.x_std_mm > 0 ? contact.x_std_mm : options_.measurement_std_mm,
                            contact.y_std_mm > 0 ? contact.y_std_mm : options_.measurement_std_mm};
  for (int k = 0; k < 2; ++k)
    track.axis[k] = {chart[k], 0, std_mm[k] * std_mm[k], 0, start_velocity_std_mm_per_s * start_velocity_std_mm_per_s};
  track.force_N = contact.force_N;
  track.force_rate_N_per_s = 0;
  out.id = track.id;
  out.phase = TouchPhase::down;
  out.vx_mm_per_s = out.vy_mm_per_s = 0;
  track.last = out;
}

void ContactTracker::follow(Track& track, const Contact& contact, const Vector2& chart, double time_s,
                            Contact& out) const {
  const double dt = std::max(0.0, time_s - track.time_s);
  // The measurement as a continuation of the track (around a sleeve, not across its seam).
  const Vector2 seen = Vector2(track.predicted[0], track.predicted[1]) +
                       chart_difference(chart, Vector2(track.predicted[0], track.predicted[1]));
  const double std_mm[2] = {contact.x_std_mm > 0 ? contact.x_std_mm : options_.measurement_std_mm,
                            contact.y_std_mm > 0 ? contact.y_std_mm : options_.measurement_std_mm};
  Vector2 place = seen;
  if (!options_.filter) {
    for (int k = 0; k < 2; ++k) {
      Axis& a = track.axis[k];
      a.v = dt > 0 ? (seen[k] - a.p) / dt : a.v;
      a.p = seen[k];
    }
  } else {
    const double q = std::pow(options_.acceleration_std_mm_per_s2, 2);
    double innovation2 = 0;  // the innovation's squared Mahalanobis length over both axes
    for (int k = 0; k < 2; ++k) {
      Axis& a = track.axis[k];  // predict to time_s (white acceleration, discrete)
      a.p += a.v * dt;
      a.ppp += 2 * dt * a.ppv + dt * dt * a.pvv + q * std::pow(dt, 4) / 4;
      a.ppv += dt * a.pvv + q * std::pow(dt, 3) / 2;
      a.pvv += q * dt * dt;
      const double s = a.ppp + std_mm[k] * std_mm[k];
      innovation2 += std::pow(seen[k] - a.p, 2) / s;
    }
    const bool jump = innovation2 > options_.jump_sigmas * options_.jump_sigmas;
    for (int k = 0; k < 2; ++k) {
      Axis& a = track.axis[k];
      const double r2 = std_mm[k] * std_mm[k];
      if (jump) {  // the press moved at once: restart here, its velocity as it was but uncertain
        a = {seen[k], a.v, r2, 0, start_velocity_std_mm_per_s * start_velocity_std_mm_per_s};
        continue;
      }
      const double s = a.ppp + r2, k0 = a.ppp / s, k1 = a.ppv / s, y = seen[k] - a.p;
      a.p += k0 * y;
      a.v += k1 * y;
      a.pvv -= k1 * a.ppv;
      a.ppv *= 1 - k0;
      a.ppp *= 1 - k0;
    }
    place = {track.axis[0].p, track.axis[1].p};
  }
  if (dt > 0) track.force_rate_N_per_s = (contact.force_N - track.force_N) / dt;
  track.force_N = contact.force_N;
  track.time_s = time_s;
  track.missed = 0;
  out.id = track.id;
  out.phase = TouchPhase::move;
  out.vx_mm_per_s = track.axis[0].v;
  out.vy_mm_per_s = track.axis[1].v;
  if (options_.filter) {
    const Vector2 shift = place - seen;
    place_on_surface(surface_, wrapped_chart_mm(surface_, place), out);
    for (int i = 0; i < out.outline.size; ++i)
      out.outline.vertices_mm[static_cast<std::size_t>(i)] =
          {static_cast<float>(out.outline.vertices_mm[static_cast<std::size_t>(i)][0] + shift.x()),
           static_cast<float>(out.outline.vertices_mm[static_cast<std::size_t>(i)][1] + shift.y())};
  }
  track.last = out;
}

void ContactTracker::end(Track& track) {
  Contact& up = ended_.emplace_back(track.last);  // within the reserve: at most one per slot
  up.phase = TouchPhase::up;
  track.live = false;
}

void ContactTracker::end_all() {
  for (Track& track : tracks_)
    if (track.live) end(track);
}

const std::vector<Contact>& ContactTracker::update(const std::vector<Contact>& contacts, double time_s) {
  if (!std::isfinite(time_s))
    throw InvalidInput("ContactTracker::update: the frame's time is not finite (" + std::to_string(time_s) + ")");
  ended_.clear();
  if (reset_pending_ || (started_ && time_s < last_time_s_)) end_all();
  reset_pending_ = false;
  started_ = true;
  last_time_s_ = time_s;

  tracked_.assign(contacts.begin(), contacts.end());  // within the reserve up to max_contacts
  const int n = std::min(static_cast<int>(contacts.size()), max_contacts_);
  for (auto c = static_cast<std::size_t>(n); c < tracked_.size(); ++c) {
    tracked_[c].id = -1;  // past the limit: untracked
    tracked_[c].phase = TouchPhase::none;
  }
  for (int c = 0; c < n; ++c) {
    charts_[static_cast<std::size_t>(c)] = chart_of(surface_, contacts[static_cast<std::size_t>(c)]);
    paired_[static_cast<std::size_t>(c)] = 0;
  }
  rows_.clear();
  for (int s = 0; s < static_cast<int>(tracks_.size()); ++s)
    if (tracks_[static_cast<std::size_t>(s)].live) {
      rows_.push_back(s);
      predict(tracks_[static_cast<std::size_t>(s)], time_s);
    }

  // The cost matrix: a row per live track; a column per contact, then one per track for leaving it
  // unpaired (its own only). Pairs past the gate, and others' columns, cost more than any way out.
  const int rows = static_cast<int>(rows_.size()), cols = n + rows;
  const double pair_most = 1 + options_.force_weight, unpaired = 2 * pair_most, barred = 4 * pair_most * cols;
  for (int r = 0; r < rows; ++r) {
    const Track& track = tracks_[static_cast<std::size_t>(rows_[static_cast<std::size_t>(r)])];
    double* row = cost_.data() + static_cast<std::size_t>(r) * static_cast<std::size_t>(cols);
    for (int c = 0; c < n; ++c) {
      const double d =
          chart_difference(charts_[static_cast<std::size_t>(c)], Vector2(track.predicted[0], track.predicted[1]))
              .norm();
      const double force = contacts[static_cast<std::size_t>(c)].force_N;
      const double relative =
          (force - track.predicted_force_N) / std::max({force, track.predicted_force_N, force_floor_N});
      row[c] = d > options_.gate_mm ? barred
                                    : std::pow(d / options_.gate_mm, 2) + options_.force_weight * relative * relative;
    }
    for (int k = 0; k < rows; ++k) row[n + k] = k == r ? unpaired : barred;
  }
  const std::span<const int> column =
      rows > 0 ? assignment_.solve({cost_.data(), static_cast<std::size_t>(rows) * static_cast<std::size_t>(cols)},
                                   rows, cols)
               : std::span<const int>{};

  for (int r = 0; r < rows; ++r) {
    Track& track = tracks_[static_cast<std::size_t>(rows_[static_cast<std::size_t>(r)])];
    const int c = column[static_cast<std::size_t>(r)];
    if (c < n &&
        cost_[static_cast<std::size_t>(r) * static_cast<std::size_t>(cols) + static_cast<std::size_t>(c)] < barred) {
      paired_[static_cast<std::size_t>(c)] = 1;
      follow(track, contacts[static_cast<std::size_t>(c)], charts_[static_cast<std::size_t>(c)], time_s,
             tracked_[static_cast<std::size_t>(c)]);
    } else if (++track.missed > options_.coast_frames) {
      end(track);
    }
  }
  for (int c = 0; c < n; ++c) {
    if (paired_[static_cast<std::size_t>(c)]) continue;
    auto slot = std::find_if(tracks_.begin(), tracks_.end(), [](const Track& t) { return !t.live; });
    if (slot == tracks_.end()) {  // every slot taken: the touch unseen longest ends now
      slot = std::max_element(tracks_.begin(), tracks_.end(),
                              [](const Track& a, const Track& b) { return a.missed < b.missed; });
      end(*slot);
    }
    start(*slot, contacts[static_cast<std::size_t>(c)], charts_[static_cast<std::size_t>(c)], time_s,
          tracked_[static_cast<std::size_t>(c)]);
  }
  return tracked_;
}

}  // namespace emit
