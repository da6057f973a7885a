// The twin's ADC (twin/adc_noise.hpp): quantisation and clipping exactly as adc_code says, the
// codes handed out, and the noise's spread as asked.
#include "emit/twin/adc_noise.hpp"

#include <cmath>
#include <vector>

#include <gtest/gtest.h>

#include "emit/sensor/adc.hpp"

namespace emit {

namespace {

// Without noise a reading is its nearest code times the step; beyond the rails it clips to code 0
// and to 2^bits − 1, which reads vref_V.
TEST(AdcNoise, NoiselessReadingsAreTheNearestCode) {
  const AdcSpec adc{10, 3.3, 0.0};
  const double step = 3.3 / 1023;
  Frame frame(2, 2);
  frame << -0.5, 100.4 * step, 100.6 * step, 4.0;
  std::mt19937_64 rng(1);
  std::uint16_t codes[4] = {};
  apply_adc(adc, frame, rng, codes);
  EXPECT_EQ(codes[0], 0);
  EXPECT_EQ(codes[1], 100);
  EXPECT_EQ(codes[2], 101);
  EXPECT_EQ(codes[3], 1023);
  EXPECT_EQ(frame(0, 0), 0.0);
  EXPECT_EQ(frame(0, 1), 100 * adc_step_V(adc));
  EXPECT_EQ(frame(1, 0), 101 * adc_step_V(adc));
  EXPECT_DOUBLE_EQ(frame(1, 1), 3.3);
}

// 10,000 readings of mid-scale with σ = 10 mV on a 16-bit ADC (step 50 µV, far below σ): their
// standard deviation is σ within 5 % (its relative standard error is 1/√(2n) = 0.7 %), their mean
// 1.65 V within 5 σ/√n = 0.5 mV.
TEST(AdcNoise, NoiseHasTheSpreadAsked) {
  const AdcSpec adc{16, 3.3, 0.01};
  Frame frame = Frame::Constant(100, 100, 1.65);
  std::mt19937_64 rng(7);
  apply_adc(adc, frame, rng);
  const double mean = frame.mean();
  const double std = std::sqrt((frame.array() - mean).square().sum() / static_cast<double>(frame.size() - 1));
  EXPECT_NEAR(mean, 1.65, 5e-4);
  EXPECT_NEAR(std, 0.01, 0.05 * 0.01);
}

}  // namespace
}  // namespace emit
