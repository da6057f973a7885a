#include "emit/twin/adc.hpp"

#include <algorithm>
#include <cmath>

namespace emit {

double adc_step_V(const AdcSpec& adc) { return adc.vref_V / (std::ldexp(1.0, adc.bits) - 1.0); }

std::uint16_t adc_code(const AdcSpec& adc, double volts) {
  const double full_scale = std::ldexp(1.0, adc.bits) - 1.0;
  return static_cast<std::uint16_t>(std::clamp(std::round(volts / adc_step_V(adc)), 0.0, full_scale));
}

double reading_noise_V(const AdcSpec& adc) {
  const double step = adc_step_V(adc);
  return std::sqrt(adc.noise_V * adc.noise_V + step * step / 12);
}

void apply_adc(const AdcSpec& adc, Frame& frame, std::mt19937_64& rng) {
  std::normal_distribution<double> noise(0.0, adc.noise_V);
  const double step = adc_step_V(adc);
  for (Index i = 0; i < frame.size(); ++i) {
    double v = frame.data()[i];
    if (adc.noise_V > 0) v += noise(rng);
    frame.data()[i] = adc_code(adc, v) * step;
  }
}

}  // namespace emit
