// The contact tracker on synthetic contacts: ids through crossings with crossing forces, merges,
// splits, coasting, the gate, ids never reused, reset; the filter's jitter and lag; velocity; a
// sleeve's seam; and no allocation per frame.
#include "emit/frame/contact_tracker.hpp"

#include <cmath>
#include <numbers>
#include <random>
#include <set>
#include <vector>

#include <gtest/gtest.h>

#include "allocation_counter.hpp"
#include "test_support.hpp"

namespace emit {
namespace {

constexpr double frame_s = 0.02;  // 50 frames/s

Contact contact_at(double x_mm, double y_mm, double force_N = 5, double std_mm = 0) {
  Contact c;
  c.x_mm = x_mm, c.y_mm = y_mm, c.force_N = force_N, c.x_std_mm = c.y_std_mm = std_mm;
  return c;
}

/// Sorted strongest first, as the contact finder and the fitter list them.
std::vector<Contact> by_force(std::vector<Contact> contacts) {
  std::sort(contacts.begin(), contacts.end(), [](const Contact& a, const Contact& b) { return a.force_N > b.force_N; });
  return contacts;
}

/// The id of the tracked contact of finger `finger` (marked in element_count, which tracking copies).
std::int64_t id_of(const std::vector<Contact>& tracked, int finger) {
  for (const Contact& c : tracked)
    if (c.element_count == finger) return c.id;
  return -2;
}

Contact finger_at(int finger, const Vector2& p, double force_N) {
  Contact c = contact_at(p.x(), p.y(), force_N, 0.2);  // its σ, as a fit reports it
  c.element_count = finger;
  return c;
}

int count_phase(const std::vector<Contact>& contacts, TouchPhase phase) {
  return static_cast<int>(
      std::count_if(contacts.begin(), contacts.end(), [&](const Contact& c) { return c.phase == phase; }));
}

// Two fingers pass each other along nearly the same line (2-6 mm apart sideways) at 50-250 mm/s,
// one force rising while the other falls, so that the list's order (strongest first) swaps half-way;
// positions with 0.2 mm of noise. Each keeps its id in every trial, filtered or not.
TEST(ContactTracker, KeepsIdsThroughCrossingsWithCrossingForces) {
  std::mt19937_64 rng(7);
  const auto uniform = [&](double a, double b) { return std::uniform_real_distribution<double>(a, b)(rng); };
  std::normal_distribution<double> noise(0, 0.2);
  for (bool filter : {false, true}) {
    int swaps = 0;
    for (int trial = 0; trial < 200; ++trial) {
      TrackerOptions options;
      options.filter = filter;
      ContactTracker tracker(options, 4);
      const double angle = uniform(0, 2 * std::numbers::pi), offset_mm = uniform(2, 6);
      const double speed_a = uniform(50, 250) * frame_s, speed_b = uniform(50, 250) * frame_s;
      const Vector2 along(std::cos(angle), std::sin(angle)), across(-along.y(), along.x()), centre(30, 30);
      const int frames = 30;
      std::int64_t id_a = -1, id_b = -1;
      bool swapped = false;
      for (int f = 0; f < frames; ++f) {
        const double s = f - 0.5 * (frames - 1), share = static_cast<double>(f) / (frames - 1);
        const Vector2 a = centre + s * speed_a * along + 0.5 * offset_mm * across;
        const Vector2 b = centre - s * speed_b * along - 0.5 * offset_mm * across;
        const Vector2 noisy_a = a + Vector2(noise(rng), noise(rng)), noisy_b = b + Vector2(noise(rng), noise(rng));
        const auto& tracked =
            tracker.update(by_force({finger_at(0, noisy_a, 2 + 8 * share), finger_at(1, noisy_b, 10 - 8 * share)}),
                           f * frame_s);
        ASSERT_EQ(tracked.size(), 2u);
        const std::int64_t now_a = id_of(tracked, 0), now_b = id_of(tracked, 1);
        if (f == 0) id_a = now_a, id_b = now_b;
        swapped = swapped || now_a != id_a || now_b != id_b;
      }
      EXPECT_NE(id_a, id_b);
      swaps += swapped;
    }
    // 2 mm apart against 0.2 mm of noise is 7σ of their difference: no swap at all.
    EXPECT_EQ(swaps, 0) << (filter ? "filtered" : "unfiltered");
  }
}

TEST(ContactTracker, PressAndReleaseGiveOneDownAndOneUp) {
  for (int coast : {0, 1, 3}) {
    TrackerOptions options;
    options.coast_frames = coast;
    ContactTracker tracker(options, 4);
    int downs = 0, moves = 0, ups = 0, frame = 0;
    for (; frame < 10; ++frame) {
      const auto& t = tracker.update({contact_at(20 + 0.1 * frame, 20, 5)}, frame * frame_s);
      downs += count_phase(t, TouchPhase::down), moves += count_phase(t, TouchPhase::move);
      ups += count_phase(tracker.ended(), TouchPhase::up);
    }
    int up_frame = -1;
    for (; frame < 20; ++frame) {
      tracker.update({}, frame * frame_s);
      if (!tracker.ended().empty()) up_frame = frame;
      ups += count_phase(tracker.ended(), TouchPhase::up);
    }
    EXPECT_EQ(downs, 1);
    EXPECT_EQ(moves, 9);
    EXPECT_EQ(ups, 1) << "coast " << coast;
    EXPECT_EQ(up_frame, 10 + coast) << "the up comes coast_frames after the first frame without it";
    EXPECT_EQ(tracker.live_count(), 0);
  }
}

TEST(ContactTracker, UpCarriesTheTouchsLastState) {
  ContactTracker tracker({}, 4);
  tracker.update({contact_at(10, 10, 3)}, 0);
  tracker.update({contact_at(11, 10, 4)}, frame_s);
  tracker.update({}, 2 * frame_s);
  tracker.update({}, 3 * frame_s);
  ASSERT_EQ(tracker.ended().size(), 1u);
  const Contact& up = tracker.ended()[0];
  EXPECT_EQ(up.phase, TouchPhase::up);
  EXPECT_EQ(up.id, 0);
  EXPECT_EQ(up.x_mm, 11);
  EXPECT_EQ(up.force_N, 4);
  EXPECT_NEAR(up.vx_mm_per_s, 1 / frame_s, 1e-9);  // 1 mm in a frame
}

TEST(ContactTracker, CoastsThroughAMissedFrame) {
  ContactTracker tracker({}, 4);  // coast_frames = 1
  tracker.update({contact_at(10, 10)}, 0);
  tracker.update({contact_at(11, 10)}, frame_s);
  tracker.update({}, 2 * frame_s);  // missed: coasting, not reported, not ended
  EXPECT_TRUE(tracker.ended().empty());
  // Seen again where constant velocity puts it (13 mm): the same touch, its velocity over the gap.
  const auto& t = tracker.update({contact_at(13, 10)}, 3 * frame_s);
  ASSERT_EQ(t.size(), 1u);
  EXPECT_EQ(t[0].id, 0);
  EXPECT_EQ(t[0].phase, TouchPhase::move);
  EXPECT_NEAR(t[0].vx_mm_per_s, 1 / frame_s, 1e-9);
}

TEST(ContactTracker, GateSeparatesTouches) {
  TrackerOptions options;
  options.gate_mm = 10;
  ContactTracker tracker(options, 4);
  tracker.update({contact_at(10, 10)}, 0);
  // 9 mm from its place: the same touch; then 11 mm further: another (and the first ends in time).
  EXPECT_EQ(tracker.update({contact_at(19, 10)}, frame_s)[0].id, 0);
  // The prediction now runs at 450 mm/s: 19 + 9 = 28; 39 is 11 mm past it.
  const auto& t = tracker.update({contact_at(39, 10)}, 2 * frame_s);
  EXPECT_EQ(t[0].id, 1);
  EXPECT_EQ(t[0].phase, TouchPhase::down);
  tracker.update({contact_at(39, 10)}, 3 * frame_s);
  ASSERT_EQ(tracker.ended().size(), 1u);  // coasted one frame, then up
  EXPECT_EQ(tracker.ended()[0].id, 0);
}

// Merge: two touches 8 mm apart become one contact between them for three frames (coast_frames 1):
// the contact keeps the touch nearer it (and of nearer force), the other coasts one frame and ends.
// Split: the contact becomes two again; the one nearer the kept touch keeps its id, the other is new.
TEST(ContactTracker, MergesAndSplitsFollowTheRule) {
  ContactTracker tracker({}, 4);
  tracker.update({contact_at(20, 20, 6), contact_at(28, 20, 4)}, 0);
  tracker.update({contact_at(20, 20, 6), contact_at(28, 20, 4)}, frame_s);
  const auto& merged = tracker.update({contact_at(23, 20, 9)}, 2 * frame_s);
  ASSERT_EQ(merged.size(), 1u);
  EXPECT_EQ(merged[0].id, 0);  // 3 mm from the first, 5 mm from the second
  EXPECT_TRUE(tracker.ended().empty());
  tracker.update({contact_at(23, 20, 9)}, 3 * frame_s);
  ASSERT_EQ(tracker.ended().size(), 1u);
  EXPECT_EQ(tracker.ended()[0].id, 1);
  EXPECT_EQ(tracker.ended()[0].phase, TouchPhase::up);
  tracker.update({contact_at(23, 20, 9)}, 4 * frame_s);
  const auto& split = tracker.update({contact_at(27, 20, 5), contact_at(22.5, 20, 5)}, 5 * frame_s);
  ASSERT_EQ(split.size(), 2u);
  EXPECT_EQ(split[1].id, 0);  // nearer the touch's place
  EXPECT_EQ(split[1].phase, TouchPhase::move);
  EXPECT_EQ(split[0].id, 2);  // a new touch: ids are not reused
  EXPECT_EQ(split[0].phase, TouchPhase::down);
}

// A merge shorter than coast_frames: the coasting touch takes up its contact again after the split.
TEST(ContactTracker, ABriefMergeKeepsBothTouches) {
  TrackerOptions options;
  options.coast_frames = 2;
  ContactTracker tracker(options, 4);
  tracker.update({contact_at(20, 20, 6), contact_at(30, 20, 4)}, 0);
  tracker.update({contact_at(25, 20, 10)}, frame_s);
  tracker.update({contact_at(25, 20, 10)}, 2 * frame_s);
  EXPECT_TRUE(tracker.ended().empty());
  const auto& t = tracker.update({contact_at(20, 20, 6), contact_at(30, 20, 4)}, 3 * frame_s);
  EXPECT_EQ(t[0].id, 0);
  EXPECT_EQ(t[1].id, 1);
  EXPECT_EQ(t[1].phase, TouchPhase::move);
}

TEST(ContactTracker, IdsAreNeverReused) {
  std::mt19937_64 rng(3);
  ContactTracker tracker({}, 4);
  std::set<std::int64_t> ended;
  std::int64_t downs = 0;
  for (int f = 0; f < 2000; ++f) {
    // 0-4 touches at random places each frame: many downs and ups.
    std::vector<Contact> contacts;
    const int n = static_cast<int>(rng() % 5);
    contacts.reserve(static_cast<std::size_t>(n));
    for (int k = 0; k < n; ++k)
      contacts.push_back(contact_at(std::uniform_real_distribution<double>(0, 60)(rng),
                                    std::uniform_real_distribution<double>(0, 60)(rng), 5));
    const auto& tracked = tracker.update(contacts, f * frame_s);
    for (const Contact& c : tracked) {
      EXPECT_EQ(ended.count(c.id), 0u) << "id " << c.id << " reported after its up";
      if (c.phase == TouchPhase::down) {
        EXPECT_EQ(c.id, downs) << "ids count up from 0, one per down";
        ++downs;
      }
    }
    for (const Contact& c : tracker.ended()) EXPECT_TRUE(ended.insert(c.id).second) << "two ups for " << c.id;
  }
  EXPECT_GT(downs, 1000);
  EXPECT_EQ(tracker.next_id(), downs);
}

TEST(ContactTracker, ResetEndsEveryTouchAndGoesOnCounting) {
  ContactTracker tracker({}, 4);
  tracker.update({contact_at(10, 10), contact_at(40, 40)}, 0);
  tracker.reset();
  const auto& t = tracker.update({contact_at(10, 10)}, frame_s);
  EXPECT_EQ(tracker.ended().size(), 2u);
  ASSERT_EQ(t.size(), 1u);
  EXPECT_EQ(t[0].id, 2);
  EXPECT_EQ(t[0].phase, TouchPhase::down);
  // A time behind the last (a source started again) does as reset() does.
  tracker.update({contact_at(10, 10)}, 0);
  EXPECT_EQ(tracker.ended().size(), 1u);
  EXPECT_EQ(tracker.update({contact_at(10, 10)}, frame_s)[0].id, 3);
}

TEST(ContactTracker, ContactsPastTheLimitAreUntracked) {
  ContactTracker tracker({}, 2);
  const auto& t = tracker.update({contact_at(10, 10), contact_at(30, 30), contact_at(50, 50)}, 0);
  ASSERT_EQ(t.size(), 3u);
  EXPECT_EQ(t[1].id, 1);
  EXPECT_EQ(t[2].id, -1);
  EXPECT_EQ(t[2].phase, TouchPhase::none);
}

/// RMS of the filtered and raw x about the truth over a still press, 0.1 mm of noise per axis.
struct Jitter {
  double raw_mm = 0, filtered_mm = 0;
};
Jitter still_jitter(double std_mm, bool give_std) {
  std::mt19937_64 rng(11);
  std::normal_distribution<double> noise(0, std_mm);
  TrackerOptions options;
  options.filter = true;
  ContactTracker tracker(options, 4);
  double raw2 = 0, filtered2 = 0;
  int n = 0;
  for (int f = 0; f < 2000; ++f) {
    const double x = 30 + noise(rng), y = 30 + noise(rng);
    const auto& t = tracker.update({contact_at(x, y, 5, give_std ? std_mm : 0)}, f * frame_s);
    if (f < 100) continue;  // the filter's settling
    raw2 += std::pow(x - 30, 2), filtered2 += std::pow(t[0].x_mm - 30, 2), ++n;
  }
  return {std::sqrt(raw2 / n), std::sqrt(filtered2 / n)};
}

// A still press: the filter's steady state (an alpha-beta filter of tracking index
// σ_a·T²/σ = 100·0.0004/0.1 = 0.4: Kalata's α = 0.588, β = 0.257) keeps (2α² + 2β − 3αβ)/(α(4 − 2α − β))
// = 0.498 of the variance, 0.706 of the rms; with the measurement noise given by the contacts or by the
// option. ±0.05: the rms's sampling (±1.6 %) and the jump test's rare restarts (χ²₂ > 16: 3e-4 a frame).
TEST(ContactTracker, FilterSmoothsAStillPress) {
  for (bool give_std : {true, false}) {
    const Jitter j = still_jitter(0.1, give_std);
    EXPECT_NEAR(j.raw_mm, 0.1, 0.005);  // 1900 samples: ±1.6 % (1σ) on an rms
    EXPECT_NEAR(j.filtered_mm / j.raw_mm, 0.706, 0.05);
  }
}

// A step: the press jumps 1-10 mm at once, more than jump_sigmas (4) of the prediction's spread (in
// the steady state above √(0.01/(1 − α)) = 0.156 mm, so 0.62 mm). The filter restarts there, so it is
// at the new place in the step's own frame: no lag. A smaller step (0.3 mm) is filtered: it moves α =
// 0.59 of the way in the step's frame, past half of it (a lag, the 50 % delay, of 0 frames).
TEST(ContactTracker, FilterDoesNotLagAStep) {
  for (double step_mm : {0.3, 1.0, 2.0, 10.0}) {
    TrackerOptions options;
    options.filter = true;
    ContactTracker tracker(options, 4);
    for (int f = 0; f < 50; ++f) tracker.update({contact_at(30, 30, 5, 0.1)}, f * frame_s);
    const auto& t = tracker.update({contact_at(30 + step_mm, 30, 5, 0.1)}, 50 * frame_s);
    EXPECT_EQ(t[0].id, 0);
    if (step_mm > 0.62) EXPECT_NEAR(t[0].x_mm, 30 + step_mm, 1e-9) << "step " << step_mm;
    else  // the steady state's α, ±0.02 for the settling left after 50 frames
      EXPECT_NEAR((t[0].x_mm - 30) / step_mm, 0.588, 0.02);
  }
}

// A finger moving at a steady 100 mm/s: both velocities are its own (the finite difference exactly
// without noise, the filter's after it settles); the filter follows with no lag at constant velocity.
TEST(ContactTracker, VelocityOfASteadyFinger) {
  for (bool filter : {false, true}) {
    TrackerOptions options;
    options.filter = filter;
    ContactTracker tracker(options, 4);
    for (int f = 0; f < 60; ++f) {
      const auto& t = tracker.update({contact_at(10 + 2.0 * f, 20 + 1.0 * f, 5, 0.1)}, f * frame_s);
      // The filter's start decays geometrically (measured: 2e-6 mm/s left after 20 frames).
      if (f < 30) continue;
      EXPECT_NEAR(t[0].vx_mm_per_s, 100, 1e-6);
      EXPECT_NEAR(t[0].vy_mm_per_s, 50, 1e-6);
      EXPECT_NEAR(t[0].x_mm, 10 + 2.0 * f, 1e-6);
    }
  }
}

// Around a sleeve, a touch crossing the seam (v from 2πR − 1 to 1 mm) is the same touch, moving on.
TEST(ContactTracker, FollowsATouchAcrossASleevesSeam) {
  Shape sleeve;
  sleeve.kind = ShapeKind::cylinder;
  sleeve.radius_mm = 10, sleeve.length_mm = 60, sleeve.angle_deg = 360;
  ContactTracker tracker({}, 4, sleeve);
  const double period = 2 * std::numbers::pi * 10;
  for (int f = 0; f < 6; ++f) {
    Contact c;
    place_on_surface(sleeve, Vector2(30, std::fmod(period - 2.5 + 1.0 * f, period)), c);
    const auto& t = tracker.update({c}, f * frame_s);
    EXPECT_EQ(t[0].id, 0);
    if (f > 0) {
      EXPECT_NEAR(t[0].vy_mm_per_s, 1 / frame_s, 1e-6);
    }
  }
}

TEST(ContactTracker, AllocatesNothingPerFrame) {
  for (bool filter : {false, true}) {
    TrackerOptions options;
    options.filter = filter;
    ContactTracker tracker(options, 4);
    std::vector<std::vector<Contact>> frames;
    frames.reserve(40);
    for (int f = 0; f < 40; ++f) {
      std::vector<Contact> contacts;
      contacts.reserve(4);
      for (int k = 0; k < (f % 10 < 5 ? 4 : f % 4); ++k) contacts.push_back(contact_at(10 + 10 * k + 0.3 * f, 20, 5));
      frames.push_back(contacts);
    }
    const test::AllocationCounter counter;
    for (int f = 0; f < 40; ++f) tracker.update(frames[static_cast<std::size_t>(f)], f * frame_s);
    tracker.reset();
    tracker.update(frames[0], 41 * frame_s);
    EXPECT_EQ(counter.count(), 0);
  }
}

TEST(ContactTracker, RefusesBadOptionsAndTimes) {
  TrackerOptions o;
  o.gate_mm = 0;
  EXPECT_EQ(test::error_of([&] { ContactTracker t(o); }), "TrackerOptions::gate_mm must be positive, got 0");
  o = {};
  o.coast_frames = -1;
  EXPECT_NE(test::error_of([&] { o.validate(); }).find("coast_frames"), std::string::npos);
  EXPECT_NE(test::error_of([] { ContactTracker t({}, 0); }).find("max_contacts"), std::string::npos);
  ContactTracker tracker;
  EXPECT_NE(test::error_of([&] { tracker.update({}, std::nan("")); }).find("not finite"), std::string::npos);
}

}  // namespace
}  // namespace emit
