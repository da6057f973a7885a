#pragma once
/// \file adc.hpp
/// The acquisition's ADC: Gaussian noise, clipping to [0, vref] and quantisation to `bits`.
#include <cstdint>
#include <random>

#include "emit/fem/forward_model.hpp"
#include "emit/sensor/sensor.hpp"

namespace emit {

/// Volts → the volts the ADC reports: v + N(0, noise_V²), clipped to [0, vref_V], rounded to
/// the nearest code of 2^bits − 1 steps over vref_V (code 2^bits − 1 reads vref_V).
void apply_adc(const AdcSpec& adc, Frame& frame, std::mt19937_64& rng);

/// The code the ADC reports for `volts`, noise aside: round(volts / step), clipped to
/// 0 … 2^bits − 1. Its inverse is code · adc_step_V (the decoder's to_volts).
std::uint16_t adc_code(const AdcSpec& adc, double volts);

/// One ADC step [V].
double adc_step_V(const AdcSpec& adc);

/// The noise of one reading [V]: the ADC's Gaussian noise and its quantisation (step²/12).
double reading_noise_V(const AdcSpec& adc);

}  // namespace emit
