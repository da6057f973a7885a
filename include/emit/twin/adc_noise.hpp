#pragma once
/// \file adc_noise.hpp
/// The twin's ADC: what the board's converter does to the sheet's exact voltages.
#include <cstdint>
#include <random>

#include "emit/core/types.hpp"
#include "emit/sensor/sensor.hpp"

namespace emit {

/// Volts → the volts the ADC reports: v + N(0, noise_V²), clipped to [0, vref_V], rounded to
/// the nearest code of 2^bits − 1 steps over vref_V (code 2^bits − 1 reads vref_V). `codes`, if
/// given, receives the codes (frame.size() of them, in the frame's ground-major order).
void apply_adc(const AdcSpec& adc, Frame& frame, std::mt19937_64& rng, std::uint16_t* codes = nullptr);

}  // namespace emit
