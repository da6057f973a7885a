// The linear methods' contacts only where the image stands out from its noise
// (FrameOptions::false_alarm_rate, model/image_noise.hpp), and the reference averaged robustly
// (average_reference, frame/reference.hpp).
#include <cmath>
#include <random>

#include <gtest/gtest.h>

#include "emit/core/errors.hpp"
#include "emit/frame/reconstructor.hpp"
#include "emit/model/image_noise.hpp"
#include "emit/model/method.hpp"
#include "emit/sensor/sensor_json.hpp"
#include "emit/twin/twin.hpp"

namespace emit {
namespace {

// The Gaussian tail: Q(k) = rate/#F. Q(4.6) = 2.1·10⁻⁶ ≈ 0.01/4700; Q(5.0) = 2.9·10⁻⁷.
TEST(ImageNoise, SignificanceSigmasFromTheGaussianTail) {
  EXPECT_NEAR(significance_sigmas(4700, 0.01), 4.6, 0.02);
  EXPECT_NEAR(significance_sigmas(35000, 0.01), 5.0, 0.02);
  EXPECT_NEAR(difference_noise_V(1e-3, 1), std::sqrt(2.0) * 1e-3, 1e-15);
  EXPECT_NEAR(difference_noise_V(1e-3, 10), std::sqrt(1.1) * 1e-3, 1e-15);
}

Sensor quick_sensor() {
  Sensor sensor = default_sensor();
  sensor.mesh.element_size_mm = 3.0;  // ~1000 triangles: quick
  return sensor;
}

// Pure-noise frames (the twin's ADC: 1 mV and quantisation) against a single-frame reference,
// the noisiest δV: the test is designed for 1 % of frames with a contact (Bonferroni, so fewer
// with correlated elements); allow 3 of 150 (P(more) < 0.1 % at a true 1 %). Without the test,
// the 50 % threshold always finds a region in the noise, so the test is what keeps them out.
TEST(LinearSignificance, NoContactOnPureNoiseFrames) {
  const Sensor sensor = quick_sensor();
  const ReconstructionModel model = build_reconstruction_model(sensor, operator_options(Method::paper), "");
  ASSERT_GT(model.reading_noise_V, 0.0);
  Reconstructor tested(model, model.uncalibrated);
  FrameOptions off;
  off.false_alarm_rate = 0;
  off.min_contact_cells = 0;
  Reconstructor untested(model, model.uncalibrated, off);
  TwinOptions twin_options;
  twin_options.noise_seed = 11;
  Twin twin(sensor, twin_options);
  int with_contact = 0, untested_with_contact = 0;
  const int frames = 150;
  for (int f = 0; f < frames; ++f) {
    if (f % 15 == 0) {  // a fresh single-frame reference every 15 frames: ten references
      const Frame reference = twin.frame({});
      tested.set_reference({reference, 1});
      untested.set_reference({reference, 1});
    }
    const Frame frame = twin.frame({});
    with_contact += !tested.process(frame).empty();
    untested_with_contact += !untested.process(frame).empty();
  }
  std::printf("pure noise: %d of %d frames with a contact (without the test: %d)\n", with_contact, frames,
              untested_with_contact);
  EXPECT_LE(with_contact, 3);
  EXPECT_GE(untested_with_contact, frames / 2);
}

// A weak press, just above the noise, is still found: over forces falling by 1.2× a step to below
// the contact law's threshold (0.002 N/mm² over 78.5 mm²: 0.16 N), every frame whose image peak
// stands above the floor (peak/floor ≥ 1.5) reports a contact within two radii of the press, and
// at least one such press is weak (peak/floor < 20).
TEST(LinearSignificance, WeakPressesAboveTheNoiseAreFound) {
  const Sensor sensor = quick_sensor();
  const ReconstructionModel model = build_reconstruction_model(sensor, operator_options(Method::paper), "");
  Reconstructor reconstructor(model, model.uncalibrated);
  TwinOptions twin_options;
  twin_options.noise_seed = 12;
  Twin twin(sensor, twin_options);
  std::vector<Frame> references;
  references.reserve(10);
  for (int i = 0; i < 10; ++i) references.push_back(twin.frame({}));
  reconstructor.set_reference(average_reference(references));
  int weak_found = 0;
  for (int step = 0; 0.6 / std::pow(1.2, step) > 0.1; ++step) {  // 0.6 N down by 1.2 a step
    const double force_N = 0.6 / std::pow(1.2, step);
    const Press press{22, 35, 5, force_N};
    const std::vector<Contact>& contacts = reconstructor.process(twin.frame({press}));
    const double z = (reconstructor.image().array() / reconstructor.significance_floor().array()).maxCoeff();
    bool near = false;
    for (const Contact& c : contacts) near = near || std::hypot(c.x_mm - press.x_mm, c.y_mm - press.y_mm) <= 10;
    std::printf("force %.4f N: peak/floor %.2f, %zu contacts, near %d\n", force_N, z, contacts.size(), near);
    if (z >= 1.5) {
      EXPECT_TRUE(near) << force_N;
      weak_found += z < 20 && near;
    }
  }
  EXPECT_GE(weak_found, 1);
}

// Ten no-contact frames, one of them very noisy (20 mV, 20× the ADC's): the robust average leaves
// it out and equals the mean of the other nine, where the plain mean moves by ~2 mV, twice the
// noise of a single reading. Ten clean frames are all kept (their distances from the median
// agree within a few %), over 20 seeds.
TEST(ReferenceAverage, OneVeryNoisyFrameIsLeftOut) {
  std::mt19937_64 rng(5);
  std::normal_distribution<double> adc(0.0, 1e-3), burst(0.0, 20e-3);
  for (int seed = 0; seed < 20; ++seed) {
    std::vector<Frame> frames(10, Frame(16, 16));
    for (Frame& f : frames)
      for (Index i = 0; i < f.size(); ++i) f.data()[i] = 0.05 + adc(rng);
    EXPECT_EQ(average_reference(frames).frames, 10) << seed;
    Frame clean_nine = Frame::Zero(16, 16);
    for (int k = 1; k < 10; ++k) clean_nine += frames[static_cast<std::size_t>(k)] / 9.0;
    for (Index i = 0; i < frames[0].size(); ++i) frames[0].data()[i] += burst(rng);
    EXPECT_EQ(average_reference(frames).frames, 9) << seed;
    EXPECT_LT((average_reference(frames).frame - clean_nine).cwiseAbs().maxCoeff(), 1e-15) << seed;
  }
  EXPECT_THROW(average_reference({}), InvalidInput);
}

}  // namespace
}  // namespace emit
