#pragma once
/// \file adc.hpp
/// The acquisition's ADC: Gaussian noise, clipping to [0, vref] and quantisation to `bits`.
#include <random>

#include "emit/fem/forward_model.hpp"
#include "emit/sensor/sensor.hpp"

namespace emit {

/// Volts → the volts the ADC reports: v + N(0, noise_V²), clipped to [0, vref_V], rounded to
/// the nearest code of 2^bits − 1 steps over vref_V (code 2^bits − 1 reads vref_V).
void apply_adc(const AdcSpec& adc, Frame& frame, std::mt19937_64& rng);

/// One ADC step [V].
double adc_step_V(const AdcSpec& adc);

/// The noise of one reading [V]: the ADC's Gaussian noise and its quantisation (step²/12).
double reading_noise_V(const AdcSpec& adc);

}  // namespace emit
