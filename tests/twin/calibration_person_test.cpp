// The scripted person calibrating a sheet without a robot (twin/calibration_person.hpp, issue 33):
// quiet first, then one finger at a time covering the sheet, then the weights; the same session
// for the same seed, whether sampled by `emit simulate --script calibration` or by `sim:calibration`.
#include "emit/twin/calibration_person.hpp"

#include <algorithm>
#include <cmath>

#include <gtest/gtest.h>

#include "emit/mesh/generate_mesh.hpp"
#include "emit/sensor/sensor_json.hpp"
#include "emit/sensor/surface.hpp"
#include "emit/twin/press_scripts.hpp"
#include "emit/twin/sim_script.hpp"
#include "test_support.hpp"

namespace emit {
namespace {

TEST(CalibrationPerson, PressesOneAtATimeCoveringTheSheetThenTheWeights) {
  const Sensor sensor = default_sensor();  // 60 × 60 mm from the origin
  const CalibrationPersonOptions options;  // 60 presses, 2-39 N, weights 2 and 5 N
  const CalibrationPerson person(sensor, options);
  const auto& presses = person.presses();
  ASSERT_EQ(presses.size(), 62u);
  double last_end_s = 0;
  int quadrant[4] = {0, 0, 0, 0};
  for (std::size_t i = 0; i < presses.size(); ++i) {
    const PersonPress& p = presses[i];
    // Quiet for the first second; held 0.4-0.6 s; lifted 0.3 s between (the options' values).
    EXPECT_GE(p.start_s, i == 0 ? options.quiet_s : last_end_s + options.lift_s - 1e-12);
    EXPECT_GE(p.end_s - p.start_s, options.min_hold_s);
    EXPECT_LE(p.end_s - p.start_s, options.max_hold_s);
    last_end_s = p.end_s;
    EXPECT_EQ(p.weight, i >= 60);
    if (p.weight) {
      EXPECT_EQ(p.press.force_N, options.weights_N[i - 60]);
    } else {
      EXPECT_GE(p.press.force_N, 2.0);
      EXPECT_LE(p.press.force_N, 39.0);
      ++quadrant[(p.press.x_mm > 30 ? 1 : 0) + (p.press.y_mm > 30 ? 2 : 0)];
    }
    // All of the disc on the sheet with 3 mm to spare.
    EXPECT_GE(chart_distance_to_border_mm(sensor.shape, sheet_outline(sensor), {p.press.x_mm, p.press.y_mm}),
              p.press.radius_mm + options.margin_mm);
  }
  // Covering the sheet: one press per cell of an 8 × 8 grid (64 ≥ 60 cells), so each quadrant's
  // 16 cells hold at least 12 presses (its 16 less the 4 cells left out), at most 16.
  for (const int count : quadrant) {
    EXPECT_GE(count, 12);
    EXPECT_LE(count, 16);
  }
  EXPECT_NEAR(person.duration_s(), presses.back().end_s + options.lift_s, 1e-12);
  // Sampled: nothing pressed at first, then the first press, lifted between.
  EXPECT_EQ(person.press_at(0.99), nullptr);
  ASSERT_NE(person.press_at(presses[0].start_s), nullptr);
  EXPECT_EQ(person.press_at(presses[0].start_s)->x_mm, presses[0].press.x_mm);
  EXPECT_EQ(person.press_at(presses[0].end_s + 0.1), nullptr);
  EXPECT_EQ(person.press_at(person.duration_s()), nullptr);
}

TEST(CalibrationPerson, SameSeedSameSessionInSimulateAndTheLiveSource) {
  const Sensor sensor = default_sensor();
  CalibrationPersonOptions options;
  options.presses = 5;
  options.seed = 7;
  PressScript script;
  script.kind = parse_script_kind("calibration");
  script.person = options;
  script.frames_per_s = 50;
  const PressSequence frames = run_script(sensor, script);
  EXPECT_EQ(script_frame_count(sensor, script), static_cast<double>(frames.size()));
  const CalibrationPerson person(sensor, options);
  EXPECT_EQ(frames.size(), static_cast<std::size_t>(std::ceil(person.duration_s() * 50)));
  // The live source: 15 untouched frames, then the person's clock at 50 frames/s.
  const Mesh mesh = generate_mesh(sensor, MeshOptions{});
  SourceOptions source;
  source.seed = 7;
  SimScript sim = parse_sim_script("sim:calibration:5");
  EXPECT_EQ(sim.person.presses, 5);
  const ScriptedPresses live(sensor, mesh, sim, source);
  int pressed = 0;
  for (std::size_t f = 0; f < frames.size(); ++f) {
    const auto presses = live.presses_of(f + static_cast<std::uint64_t>(source.untouched_frames));
    ASSERT_EQ(presses.size(), frames[f].size()) << "frame " << f;
    if (presses.empty()) continue;
    ++pressed;
    EXPECT_NEAR(presses[0].x_mm, frames[f][0].x_mm, 1e-9);
    EXPECT_EQ(presses[0].force_N, frames[f][0].force_N);
  }
  // 7 presses (5 fingers, 2 weights) of 0.4-0.6 s at 50 frames/s: 20-30 frames each.
  EXPECT_GE(pressed, 7 * 20);
  EXPECT_LE(pressed, 7 * 30 + 7);
  EXPECT_EQ(test::error_of([] { parse_sim_script("sim:calibration:x"); }),
            "source \"sim:calibration:x\": \"x\" is not a number");
  EXPECT_EQ(test::error_of([] { parse_sim_script("sim:calibration:2.5"); }),
            "source \"sim:calibration:2.5\": expected sim:calibration or sim:calibration:PRESSES (a count)");
  options.weights_N = {0};
  EXPECT_EQ(test::error_of([&] { CalibrationPerson(sensor, options); }),
            "CalibrationPersonOptions::weights_N must be positive, got 0");
}

}  // namespace
}  // namespace emit
