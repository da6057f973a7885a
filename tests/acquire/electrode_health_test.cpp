// Dead electrodes: found from the frames, left out, and the reconstruction still works.
#include "emit/acquire/electrode_health.hpp"
#include "emit/model/method.hpp"

#include <gtest/gtest.h>

#include "emit/core/errors.hpp"
#include "emit/eval/evaluation.hpp"
#include "emit/sensor/sensor_json.hpp"
#include "emit/twin/press_scripts.hpp"

namespace emit {
namespace {

TEST(ElectrodeHealth, FindsADisconnectedElectrodeAndReconstructsWithoutIt) {
  const Sensor sensor = default_sensor();
  TwinOptions options;
  options.dead_electrode = 5;
  options.mesh_seed = 5;
  Twin twin(sensor, options);
  PressStyle style;
  style.margin_mm = 6;
  const SimulatedRun run = simulate_run(twin, grid_script(sensor, 12, 2, style));
  const auto dead = find_dead_electrodes(run.frames, sensor.adc);
  ASSERT_EQ(dead.size(), 1u);
  EXPECT_EQ(dead[0].electrode, 5);
  // Without electrode 5's 30 measurements the paper's method keeps its accuracy class: the
  // 210 others still see every press (bound: the paper's 3.49 mm + 2 std of 1.56 mm).
  const ReconstructionModel model = build_reconstruction_model(sensor, operator_options(Method::paper), "", {5});
  EXPECT_EQ(model.measurements.size(), 15 * 14);
  Reconstructor reconstructor(model, LinearCalibration::uncalibrated(sensor));
  const LocalisationResult r = localisation_errors(reconstructor, run, 0.5);
  std::printf("dead electrode 5 left out: %.2f +/- %.2f mm over %d presses\n", r.image_centroid.mean,
              r.image_centroid.std, r.image_centroid.count);
  EXPECT_LE(r.image_centroid.mean, 3.49 + 2 * 1.56);
}

TEST(ElectrodeHealth, HealthyFramesHaveNoDeadElectrode) {
  const Sensor sensor = default_sensor();
  Twin twin(sensor);
  const std::vector<Frame> frames = {twin.frame({{30, 30, 5, 10}}), twin.frame({{10, 50, 5, 3}}), twin.frame({})};
  EXPECT_TRUE(find_dead_electrodes(frames, sensor.adc).empty());
  EXPECT_TRUE(find_dead_electrodes({twin.frame({})}, sensor.adc).empty());  // no signal, no verdict
}

// Volts below 0 or above the ADC's reference used to be read without a word (volts in mV, or
// another board's frames). The rail tolerance is max(2 steps, 5 σ) = 5 mV on the default ADC.
TEST(ElectrodeHealth, ReadingsAnAdcCannotGiveAreAnError) {
  const Sensor sensor = default_sensor();
  Frame frame = Frame::Zero(16, 16);
  frame(3, 4) = -0.004;  // within the tolerance of a rail: noise
  EXPECT_NO_THROW(check_readings_in_range(frame, sensor.adc, "f.csv:1"));
  frame(3, 4) = 3.304;
  EXPECT_NO_THROW(check_readings_in_range(frame, sensor.adc, "f.csv:1"));
  frame(3, 4) = -0.2;
  try {
    check_readings_in_range(frame, sensor.adc, "f.csv:1");
    FAIL() << "no error";
  } catch (const InvalidInput& e) {
    EXPECT_STREQ(e.what(), "f.csv:1: ground 3, sense 4 reads -0.2 V, outside the ADC's 0 to 3.3 V (sensor \"adc\")");
  }
  frame(3, 4) = 1200;  // millivolts
  EXPECT_THROW(check_readings_in_range(frame, sensor.adc, "f.csv:1"), InvalidInput);
}

// A pressed frame given as the reference was once taken without a word.
TEST(ElectrodeHealth, APressedReferenceLooksPressed) {
  const Sensor sensor = default_sensor();
  Twin twin(sensor);
  EXPECT_FALSE(looks_pressed(twin.frame({}), sensor.adc));
  EXPECT_TRUE(looks_pressed(twin.frame({{30, 30, 5, 10}}), sensor.adc));
}

// The tally, fed a frame at a time, finds what the whole-vector function finds.
TEST(ElectrodeHealth, TheTallyAgreesWithTheWholeVector) {
  const Sensor sensor = default_sensor();
  TwinOptions options;
  options.dead_electrode = 9;
  Twin twin(sensor, options);
  const std::vector<Frame> frames = {twin.frame({{30, 30, 5, 10}}), twin.frame({}), twin.frame({{15, 40, 5, 8}})};
  ElectrodeHealthTally tally(16, sensor.adc);
  for (const Frame& frame : frames) tally.add(frame);
  const auto dead = tally.dead();
  ASSERT_EQ(dead.size(), 1u);
  EXPECT_EQ(dead[0].electrode, 9);
  EXPECT_EQ(dead[0].reason, find_dead_electrodes(frames, sensor.adc)[0].reason);
  EXPECT_EQ(dead[0].reason, "reads 0 V as the sensed electrode in all 2 frames with signal");
}

}  // namespace
}  // namespace emit
