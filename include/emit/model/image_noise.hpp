#pragma once
/// \file image_noise.hpp
/// How much of a linear image is noise (docs/physics.md, "Contacts only where the image is
/// significant"). White reading noise σ_n in δV puts σ_n·‖row k of R‖ into element k of the
/// image; with no press the image is that noise alone, and its maximum over #F elements stays
/// below k·σ with k from the Gaussian tail (significance_sigmas).
#include "emit/core/types.hpp"
#include "emit/sensor/adc.hpp"  // reading_noise_V, one reading's σ

namespace emit {

/// σ of δV = V − V_ref when the reference is the mean of `reference_frames` frames:
/// σ_n·√(1 + 1/n) (√2·σ_n for a single-frame reference). \pre reference_frames ≥ 1.
double difference_noise_V(double reading_noise_V, double reference_frames);

/// k such that #F independent standard Gaussians all stay below k with probability
/// 1 − false_alarm_rate: Q(k) = false_alarm_rate/#F (Bonferroni; the image's elements are
/// correlated, so fewer are independent and the real rate is lower). 6.8k elements at 1 %: 4.6.
/// \throw InvalidInput for elements < 1 or a rate outside (0, 1).
double significance_sigmas(Index elements, double false_alarm_rate);

}  // namespace emit
