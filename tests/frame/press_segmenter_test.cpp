// Stable presses found in a stream of frames (frame/press_segmenter.hpp, issue 33): on the twin's
// frames of a scripted person calibrating (twin/calibration_person.hpp), every press is found once,
// in its own frames, and none in quiet frames; the thresholds stand on the noise model.
#include "emit/frame/press_segmenter.hpp"

#include <cmath>
#include <random>

#include <gtest/gtest.h>

#include "allocation_counter.hpp"
#include "emit/sensor/adc.hpp"
#include "emit/sensor/sensor_json.hpp"
#include "emit/twin/calibration_person.hpp"
#include "emit/twin/twin.hpp"
#include "test_support.hpp"

namespace emit {
namespace {

constexpr double frames_per_s = 25;  // the person's clock: a 0.4 s press is 10 frames

Sensor small_sensor() {
  Sensor sensor = load_sensor(test::source_path("examples/sensors/square30.json"));
  sensor.mesh.element_size_mm = 2.0;  // the twin at 2 mm: quick under the sanitizers
  return sensor;
}

TEST(PressSegmenter, FindsEveryScriptedPressOnceAndNothingInQuietFrames) {
  const Sensor sensor = small_sensor();
  CalibrationPersonOptions options;
  options.presses = 4;  // and the two weights, 2 N and 5 N: the faintest presses of a session
  options.seed = 3;
  const CalibrationPerson person(sensor, options);
  const PressSequence truth = person.frames(frames_per_s);
  Twin twin(sensor);
  std::vector<Frame> frames;
  for (const auto& presses : truth) frames.push_back(twin.frame(presses));
  // The reference and the noise from the first 20 of the 25 quiet frames (1 s).
  const std::vector<Frame> quiet(frames.begin(), frames.begin() + 20);
  const Reference reference = average_reference(quiet);
  const double measured_V = measured_reading_noise_V(quiet);
  // The noise model (sensor/adc.hpp): an untouched sheet reads 0 V (no current flows), so the
  // ADC clips half of each reading's noise: a rectified Gaussian's spread, √(1/2 − 1/(2π)) = 0.58
  // of σ, more with the quantisation step; never more than σ. Under a press the readings are clear
  // of 0 and their noise is σ: the segmenter takes the model's, the larger.
  const double model_V = reading_noise_V(sensor.adc);
  EXPECT_GT(measured_V, 0.5 * model_V);
  EXPECT_LT(measured_V, 1.0 * model_V);
  const double noise_V = std::max(measured_V, model_V);
  PressSegmenter segmenter(reference, noise_V);
  EXPECT_NEAR(segmenter.untouched_noise_V(), noise_V * std::sqrt(1 + 1.0 / reference.frames), 1e-15);
  std::vector<SegmentedPress> found;
  for (std::size_t f = 20; f < frames.size(); ++f) {
    if (f < 25) {  // quiet: each frame's change at most σ_u (its rms within 20 %: the header's bound)
      EXPECT_FALSE(segmenter.push(frames[f]));
      EXPECT_LT(segmenter.change_rms_V(), 1.2 * segmenter.untouched_noise_V());
      EXPECT_FALSE(segmenter.touched());
      continue;
    }
    if (segmenter.push(frames[f])) found.push_back(segmenter.press());
  }
  ASSERT_EQ(found.size(), person.presses().size());
  for (std::size_t i = 0; i < found.size(); ++i) {
    // Its run lies in the scripted press's frames (numbered from frame 20, the first pushed).
    const PersonPress& p = person.presses()[i];
    const double first_s = static_cast<double>(found[i].first_frame + 20) / frames_per_s;
    const double last_s = static_cast<double>(found[i].last_frame + 20) / frames_per_s;
    EXPECT_GE(first_s, p.start_s) << "press " << i;
    EXPECT_LT(last_s, p.end_s) << "press " << i;
    // All of it but the landing frame: held ≥ 0.4 s, 10 frames or more at 25 frames/s, less the
    // landing one and trim_frames (1) at either end.
    EXPECT_GE(found[i].frames_averaged,
              static_cast<int>(std::floor(p.end_s * frames_per_s) - std::ceil(p.start_s * frames_per_s)) - 3)
        << "press " << i;
    // Its mean is the press's noise-free frame within the noise of a mean of that many frames:
    // σ/√n per reading, the rms over readings likewise (4× for the bound's margin).
    const Frame exact = twin.exact_frame({p.press});
    const double rms_error_V =
        std::sqrt((found[i].frame - exact).squaredNorm() / static_cast<double>(exact.size() - exact.rows()));
    EXPECT_LT(rms_error_V,
              4 * reading_noise_V(sensor.adc) / std::sqrt(found[i].frames_averaged) + reading_noise_V(sensor.adc) / 2)
        << "press " << i;
    EXPECT_GT(found[i].change_rms_V, segmenter.press_threshold_V());
  }
  // Quiet for a long while after: nothing more found, and no allocation per frame.
  std::mt19937_64 rng(5);
  std::normal_distribution<double> noise(0, noise_V);
  Frame quiet_frame = reference.frame;
  const test::AllocationCounter counter;
  for (int f = 0; f < 2000; ++f) {
    for (Index i = 0; i < quiet_frame.size(); ++i) quiet_frame.data()[i] = reference.frame.data()[i] + noise(rng);
    EXPECT_FALSE(segmenter.push(quiet_frame));
    EXPECT_FALSE(segmenter.touched());
  }
  for (const Frame& frame : frames) segmenter.push(frame);  // presses again, their buffers warm
  EXPECT_EQ(counter.count(), 0);
}

// A touch that never holds still (a finger rolling across) is no press; one that holds still long
// enough twice in a touch is one press, the longer hold.
TEST(PressSegmenter, OnePressPerTouchAndNoneWithoutAStableRun) {
  const int N = 4;
  Reference reference{Frame::Constant(N, N, 1.0), 10};
  const double noise_V = 1e-3;
  PressSegmenter segmenter(reference, noise_V);
  const auto frame_of = [&](double change_V) {
    Frame f = reference.frame;
    f.array() += change_V;
    return f;
  };
  // Rolling: every frame 10 mV on from the last, far beyond 4·√2 mV + 5 % of the change... for
  // changes below 0.1 V; then lifted.
  for (int f = 1; f <= 8; ++f) EXPECT_FALSE(segmenter.push(frame_of(0.01 * f)));
  EXPECT_TRUE(segmenter.touched());
  EXPECT_FALSE(segmenter.push(frame_of(0)));
  EXPECT_FALSE(segmenter.touched());
  // Held at 50 mV for 6 frames, moved to 80 mV for 9: one press, the 80 mV hold, its middle
  // (the landing on 80 and the trim frame at either end left out: 6 frames).
  for (int f = 0; f < 6; ++f) EXPECT_FALSE(segmenter.push(frame_of(0.05)));
  for (int f = 0; f < 9; ++f) EXPECT_FALSE(segmenter.push(frame_of(0.08)));
  ASSERT_TRUE(segmenter.push(frame_of(0)));
  EXPECT_NEAR(segmenter.press().change_rms_V, 0.08, 1e-12);
  EXPECT_EQ(segmenter.press().frames_averaged, 6);
  EXPECT_EQ(segmenter.press().first_frame, 9u + 6 + 1);  // the second frame at 80 mV
  EXPECT_EQ(test::error_of([&] { PressSegmenter(reference, 0); }),
            "press segmentation: a reading's noise must be positive, got 0.000000 V");
  PressSegmenterOptions bad;
  bad.min_frames = 2;
  EXPECT_EQ(test::error_of([&] { PressSegmenter(reference, noise_V, bad); }),
            "PressSegmenterOptions::min_frames must be at least 3, got 2");
  EXPECT_EQ(test::error_of([&] { segmenter.push(Frame::Zero(3, 3)); }),
            "press segmentation: frame 25 is 3 x 3, the reference 4 x 4");
}

}  // namespace
}  // namespace emit
