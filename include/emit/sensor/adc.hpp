#pragma once
/// \file adc.hpp
/// The acquisition's ADC as the host sees it: volts ↔ codes, its step and the noise of a reading.
/// (The twin adds the noise itself: twin/adc_noise.hpp.)
#include <cstdint>

#include "emit/sensor/sensor.hpp"

namespace emit {

/// The code the ADC reports for `volts`, noise aside: round(volts / step), clipped to
/// 0 … 2^bits − 1. Its inverse is code · adc_step_V (the decoder's to_volts).
std::uint16_t adc_code(const AdcSpec& adc, double volts);

/// One ADC step [V].
double adc_step_V(const AdcSpec& adc);

/// Readings at or above this [V] are at the ADC's top code (within half a step of vref): clipped,
/// the true value unknown above it (frame/masked_readings.hpp masks them).
double clipped_at_V(const AdcSpec& adc);

/// The noise of one reading [V]: the ADC's Gaussian noise and its quantisation (step²/12).
double reading_noise_V(const AdcSpec& adc);

}  // namespace emit
