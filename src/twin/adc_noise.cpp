#include "emit/twin/adc_noise.hpp"

#include "emit/sensor/adc.hpp"

namespace emit {

void apply_adc(const AdcSpec& adc, Frame& frame, std::mt19937_64& rng, std::uint16_t* codes) {
  std::normal_distribution<double> noise(0.0, adc.noise_V);
  const double step = adc_step_V(adc);
  for (Index i = 0; i < frame.size(); ++i) {
    double v = frame.data()[i];
    if (adc.noise_V > 0) v += noise(rng);
    const std::uint16_t code = adc_code(adc, v);
    frame.data()[i] = code * step;
    if (codes) codes[i] = code;
  }
}

}  // namespace emit
