// Press scripts: every press on the sheet and inside its margin, counts, separations, seeds.
#include "emit/twin/press_scripts.hpp"

#include <cmath>

#include <gtest/gtest.h>

#include "emit/core/errors.hpp"
#include "emit/sensor/sensor_json.hpp"
#include "test_support.hpp"

namespace emit {
namespace {

void expect_inside_margin(const Sensor& sensor, const PressSequence& sequence, double margin_mm) {
  for (const auto& frame : sequence)
    for (const Press& p : frame) {
      const Vector2 c(p.x_mm, p.y_mm);
      EXPECT_TRUE(sensor.border->contains(c)) << p.x_mm << ", " << p.y_mm;
      EXPECT_GE(sensor.border->distance_to_border_mm(c), margin_mm - 1e-12) << p.x_mm << ", " << p.y_mm;
    }
}

TEST(PressScripts, GridCoversTheSheetAtItsPitch) {
  const Sensor sensor = default_sensor();
  PressStyle style;
  style.margin_mm = 5;
  const PressSequence grid = grid_script(sensor, 10, 0, style);
  // Centred 10 mm grid on 60 mm: nodes at 0, 10, …, 60; those ≥ 5 mm inside are 10 … 50: 5 × 5.
  EXPECT_EQ(grid.size(), 25u);
  expect_inside_margin(sensor, grid, 5);
  const PressSequence jittered = grid_script(sensor, 10, 2, style);
  ASSERT_EQ(jittered.size(), grid.size());
  double largest_shift = 0;
  for (std::size_t f = 0; f < grid.size(); ++f) {
    const double shift =
        std::max(std::abs(jittered[f][0].x_mm - grid[f][0].x_mm), std::abs(jittered[f][0].y_mm - grid[f][0].y_mm));
    EXPECT_LE(shift, 2.0);
    largest_shift = std::max(largest_shift, shift);
  }
  EXPECT_GT(largest_shift, 0.5);  // the jitter does move presses
}

TEST(PressScripts, RandomPressesStayInsideAndFollowTheSeed) {
  const Sensor sensor = load_sensor(test::source_path("examples/sensors/circle40.json"));
  PressStyle style;
  style.margin_mm = 6;
  style.min_force_N = 2, style.max_force_N = 20;
  const PressSequence a = random_script(sensor, 200, style);
  ASSERT_EQ(a.size(), 200u);
  expect_inside_margin(sensor, a, 6);
  for (const auto& frame : a) {
    EXPECT_GE(frame[0].force_N, 2.0);
    EXPECT_LE(frame[0].force_N, 20.0);
  }
  EXPECT_EQ(random_script(sensor, 200, style)[17][0].x_mm, a[17][0].x_mm);  // same seed, same presses
  style.seed = 2;
  EXPECT_NE(random_script(sensor, 200, style)[17][0].x_mm, a[17][0].x_mm);
}

TEST(PressScripts, TwoFingersAreTheAskedDistanceApart) {
  const Sensor sensor = default_sensor();
  const PressSequence two = two_finger_script(sensor, 100, 12, 40, PressStyle{});
  expect_inside_margin(sensor, two, PressStyle{}.margin_mm);
  for (const auto& frame : two) {
    ASSERT_EQ(frame.size(), 2u);
    const double d = std::hypot(frame[0].x_mm - frame[1].x_mm, frame[0].y_mm - frame[1].y_mm);
    EXPECT_GE(d, 12 - 1e-9);
    EXPECT_LE(d, 40 + 1e-9);
  }
}

TEST(PressScripts, MovingPressFollowsAStraightLine) {
  const PressSequence path = moving_script(default_sensor(), 5, Vector2(10, 10), Vector2(50, 30), PressStyle{});
  ASSERT_EQ(path.size(), 5u);
  EXPECT_DOUBLE_EQ(path[2][0].x_mm, 30);
  EXPECT_DOUBLE_EQ(path[2][0].y_mm, 20);
  EXPECT_THROW(moving_script(default_sensor(), 5, Vector2(10, 10), Vector2(70, 30), PressStyle{}), InvalidInput);
}

// Three and four fingers: every two at least the separation apart, inside the margin, seeded,
// each with the style's profile.
// Two fingers crossing: each on its own straight line at constant speed, the lines parallel and the
// drawn separation apart (the least distance, half-way), the forces crossing there; seeds differ.
TEST(PressScripts, CrossingFingers) {
  const Sensor sensor = default_sensor();
  PressStyle style;
  style.min_force_N = 2, style.max_force_N = 12;
  for (std::uint64_t seed = 1; seed <= 20; ++seed) {
    style.seed = seed;
    const PressSequence s = crossing_script(sensor, 31, 12, 20, style);
    ASSERT_EQ(s.size(), 31u);
    expect_inside_margin(sensor, s, style.margin_mm);
    double closest = 1e9;
    int closest_frame = -1;
    for (int f = 0; f < 31; ++f) {
      const auto& frame = s[static_cast<std::size_t>(f)];
      ASSERT_EQ(frame.size(), 2u);
      const double d = std::hypot(frame[0].x_mm - frame[1].x_mm, frame[0].y_mm - frame[1].y_mm);
      if (d < closest) closest = d, closest_frame = f;
      if (f > 1) {  // constant velocity: equal steps (round-off of sums of ~60 mm)
        for (int k = 0; k < 2; ++k) {
          const Press &a = s[f - 2][k], &b = s[f - 1][k], &c = frame[k];
          EXPECT_NEAR(c.x_mm - b.x_mm, b.x_mm - a.x_mm, 1e-9);
          EXPECT_NEAR(c.y_mm - b.y_mm, b.y_mm - a.y_mm, 1e-9);
        }
      }
    }
    EXPECT_EQ(closest_frame, 15);  // the middle frame
    EXPECT_GE(closest, 12 - 1e-9);
    EXPECT_LE(closest, 20 + 1e-9);
    EXPECT_LT(s[0][0].force_N, s[0][1].force_N);  // the first rises, the second falls …
    EXPECT_GT(s[30][0].force_N, s[30][1].force_N);
    EXPECT_NEAR(s[15][0].force_N, s[15][1].force_N, 1e-9);  // … equal half-way
    EXPECT_NEAR(s[0][0].force_N, s[30][1].force_N, 1e-12);
  }
  style.seed = 1;
  const PressSequence a = crossing_script(sensor, 31, 12, 20, style);
  style.seed = 2;
  EXPECT_NE(crossing_script(sensor, 31, 12, 20, style)[0][0].x_mm, a[0][0].x_mm);
  EXPECT_THROW(crossing_script(sensor, 1, 12, 20, style), InvalidInput);
  EXPECT_THROW(crossing_script(sensor, 30, 70, 80, style), InvalidInput);  // no room on a 60 mm sheet
  EXPECT_EQ(parse_script_kind("crossing"), PressScript::Kind::crossing);
}

TEST(PressScripts, FingersAreAtLeastTheSeparationApart) {
  const Sensor sensor = default_sensor();
  PressStyle style;
  style.profile = PressProfile::spherical;
  for (int fingers : {3, 4}) {
    const PressSequence frames = fingers_script(sensor, 50, fingers, 12, style);
    ASSERT_EQ(frames.size(), 50u);
    expect_inside_margin(sensor, frames, style.margin_mm);
    double closest = 1e9;
    for (const auto& frame : frames) {
      ASSERT_EQ(frame.size(), static_cast<std::size_t>(fingers));
      for (std::size_t i = 0; i < frame.size(); ++i) {
        EXPECT_EQ(frame[i].profile, PressProfile::spherical);
        for (std::size_t j = 0; j < i; ++j)
          closest = std::min(closest, std::hypot(frame[i].x_mm - frame[j].x_mm, frame[i].y_mm - frame[j].y_mm));
      }
    }
    EXPECT_GE(closest, 12.0 - 1e-12) << fingers;
    EXPECT_LT(closest, 20.0) << fingers;  // 50 frames of random places come near the bound
    EXPECT_EQ(fingers_script(sensor, 50, fingers, 12, style)[7][2].x_mm, frames[7][2].x_mm);  // seeded
  }
  PressScript script;
  script.kind = parse_script_kind("four-finger");
  script.frames = 2;
  EXPECT_EQ(run_script(sensor, script)[1].size(), 4u);
  EXPECT_EQ(parse_script_kind("three-finger"), PressScript::Kind::three_finger);
  // Four presses 55 mm apart do not fit in the 50 × 50 mm inside the margin (at best, its corners
  // are 50 mm apart).
  try {
    fingers_script(sensor, 1, 4, 55, style);
    FAIL() << "no error";
  } catch (const InvalidInput& e) {
    EXPECT_STREQ(e.what(), "no room on the sheet for 4 presses 55 mm apart");
  }
}

}  // namespace
}  // namespace emit
