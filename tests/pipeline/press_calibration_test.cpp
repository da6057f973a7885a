// Calibration from presses (pipeline/press_calibration.hpp), on a coarse 30 mm sheet: the inputs
// checked with one-line errors, and the paper method's eq. 8 fitted to the twin's presses on
// single presses only. (Contact fitting's calibration runs end to end in tests/cli/cli_test.cpp.)
#include "emit/pipeline/press_calibration.hpp"

#include <cmath>
#include <limits>
#include <numbers>

#include <gtest/gtest.h>

#include "emit/core/errors.hpp"
#include "emit/sensor/sensor_json.hpp"
#include "emit/twin/twin.hpp"
#include "test_support.hpp"

namespace emit {
namespace {

Sensor coarse_sensor() {
  Sensor sensor = load_sensor(test::source_path("examples/sensors/square30.json"));
  sensor.mesh.element_size_mm = 2.0;  // ~500 triangles: quick
  return sensor;
}

TEST(PressCalibration, FramesAndTruthMustMatch) {
  const Sensor sensor = coarse_sensor();
  const Frame zero = Frame::Zero(16, 16);
  try {
    calibrate_from_presses(sensor, {}, {zero, 1}, {zero, zero}, {{}});
    FAIL() << "no error";
  } catch (const InvalidInput& e) {
    EXPECT_STREQ(e.what(), "calibration: 1 frames of presses for 2 frames");
  }
  // Contact fitting calibrates on single presses; two at once are skipped, so none is left.
  const PressSequence two_at_once = {{{10, 10, 2.5, 5}, {20, 20, 2.5, 5}}};
  try {
    calibrate_from_presses(sensor, {}, {zero, 1}, {zero}, two_at_once);
    FAIL() << "no error";
  } catch (const InvalidInput& e) {
    EXPECT_STREQ(e.what(), "calibration: no single presses to calibrate on");
  }
}

// Presses of unknown place or force: contact fitting needs at least two of known force for the
// contact law, and the linear methods need every place and force.
TEST(PressCalibration, SaysWhatPressesOfUnknownPlaceOrForceLack) {
  const Sensor sensor = coarse_sensor();
  const Frame zero = Frame::Zero(16, 16);
  const double unknown = std::numeric_limits<double>::quiet_NaN();
  PressSequence presses(3, {Press{unknown, unknown, 5, unknown}});
  presses[0][0].force_N = 10;  // one weight of known force
  try {
    calibrate_from_presses(sensor, {}, {zero, 1}, {zero, zero, zero}, presses);
    FAIL() << "no error";
  } catch (const InvalidInput& e) {
    EXPECT_STREQ(e.what(),
                 "calibration: 1 single presses of known force; the contact law (R = alpha P^gamma) needs at least 2, "
                 "of different forces: put a known weight down, or press on a scale");
  }
  PressCalibrationOptions paper;
  paper.method = Method::paper;
  try {
    calibrate_from_presses(sensor, paper, {zero, 1}, {zero, zero, zero}, presses);
    FAIL() << "no error";
  } catch (const InvalidInput& e) {
    EXPECT_STREQ(e.what(),
                 "calibration: frame 0's press has no place or no force; the linear methods calibrate on presses of "
                 "known place and force (contact fitting, --method fit, takes the others)");
  }
}

// Eq. 8 fitted on six single presses of 0.1 to 0.35 N/mm² (a two-finger frame among them is
// skipped): the calibrated pressures' rms error on them within a fifth of the range, the paper
// method's class (its 60 mm sheet: 0.046 N/mm² on hardware, emit eval 0.076 over 0.5 full scale).
TEST(PressCalibration, PaperMethodFitsEquationEightOnSinglePresses) {
  const Sensor sensor = coarse_sensor();
  Twin twin(sensor);
  PressSequence truth;
  for (int i = 0; i < 6; ++i) {
    const double pressure = 0.1 + 0.05 * i, radius = 2.5;
    truth.push_back({{8.0 + 3 * i, 22.0 - 2 * i, radius, pressure * std::numbers::pi * radius * radius}});
  }
  truth.push_back({{8, 8, 2.5, 3}, {22, 22, 2.5, 3}});
  std::vector<Frame> frames;
  for (const auto& presses : truth) frames.push_back(twin.frame(presses));
  PressCalibrationOptions options;
  options.method = Method::paper;
  options.lambda2 = 3e3;
  const PressCalibrationResult result = calibrate_from_presses(sensor, options, {twin.frame({}), 1}, frames, truth);
  ASSERT_TRUE(std::holds_alternative<LinearCalibration>(result.calibration));
  EXPECT_EQ(result.presses, 6u);
  EXPECT_EQ(result.lambda2, 3e3);
  EXPECT_FALSE(result.sheet.has_value());
  EXPECT_LT(result.rms_N_per_mm2, 0.2 * 0.25);
  EXPECT_GE(result.max_abs_N_per_mm2, result.rms_N_per_mm2);  // the largest is no smaller than the rms
}

}  // namespace
}  // namespace emit
