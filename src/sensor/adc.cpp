#include "emit/sensor/adc.hpp"

#include <algorithm>
#include <cmath>

namespace emit {

double adc_step_V(const AdcSpec& adc) { return adc.vref_V / (std::ldexp(1.0, adc.bits) - 1.0); }

double clipped_at_V(const AdcSpec& adc) { return adc.vref_V - 0.5 * adc_step_V(adc); }

std::uint16_t adc_code(const AdcSpec& adc, double volts) {
  const double full_scale = std::ldexp(1.0, adc.bits) - 1.0;
  return static_cast<std::uint16_t>(std::clamp(std::round(volts / adc_step_V(adc)), 0.0, full_scale));
}

double reading_noise_V(const AdcSpec& adc) {
  const double step = adc_step_V(adc);
  return std::sqrt(adc.noise_V * adc.noise_V + step * step / 12);
}

}  // namespace emit
