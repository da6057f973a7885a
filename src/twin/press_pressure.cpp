#include "emit/twin/press_pressure.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "emit/core/errors.hpp"

namespace emit {

namespace {

/// e^(−z) I0(z), the exponentially scaled modified Bessel function, for z ≥ 0: the library's I0
/// while it is finite and accurate, then its asymptotic series (relative error < 1e-9 at z ≥ 40).
double scaled_bessel_i0(double z) {
  if (z < 40) return std::exp(-z) * std::cyl_bessel_i(0.0, z);
  const double t = 1.0 / (8.0 * z);
  return (1.0 + t * (1.0 + t * (4.5 + t * (37.5 + t * 459.375)))) / std::sqrt(2.0 * std::numbers::pi * z);
}

}  // namespace

RadialPressure::RadialPressure(const Press& press, double blur_mm) : press_(press), support_mm_(press.radius_mm) {
  if (!(blur_mm >= 0) || !std::isfinite(blur_mm)) throw InvalidInput("cover blur must be finite and >= 0 mm");
  if (blur_mm == 0) return;
  const double s2 = blur_mm * blur_mm, a = press.radius_mm;
  support_mm_ = a + 4 * blur_mm;
  // The table: 32 points per blur or per radius, whichever is finer (linear interpolation errs by
  // step²·P''/8, ~1e-4 of P).
  step_mm_ = std::min(blur_mm, a) / 32;
  const auto points = static_cast<std::size_t>(std::ceil(support_mm_ / step_mm_)) + 2;
  // The source over its disc, in s = a·sin θ for the spherical profile (so √(1 − s²/a²) = cos θ
  // is smooth) and s uniform for the flat one; midpoint rule, 64 nodes per blur width (its error,
  // h²/24 of the integrand's slope, is then ~1e-5).
  const int nodes = std::max(256, static_cast<int>(std::ceil(64 * a / blur_mm)));
  std::vector<double> s(static_cast<std::size_t>(nodes)), weight(s.size());  // weight: P(s)·s·ds
  for (int k = 0; k < nodes; ++k) {
    const double t = (k + 0.5) / nodes;
    if (press.profile == PressProfile::flat) {
      s[k] = a * t;
      weight[k] = press.pressure_N_per_mm2() * s[k] * (a / nodes);
    } else {
      const double theta = 0.5 * std::numbers::pi * t, dtheta = 0.5 * std::numbers::pi / nodes;
      s[k] = a * std::sin(theta);
      weight[k] = press.pressure_at_N_per_mm2(s[k]) * s[k] * a * std::cos(theta) * dtheta;
    }
  }
  // Radial 2-D convolution with the Gaussian G(r) = exp(−r²/2σ²)/(2πσ²): integrating over the
  // angle between the two points leaves
  //   P_b(ρ) = ∫ P(s) s/σ² · exp(−(ρ² + s²)/2σ²) I0(ρs/σ²) ds
  //          = ∫ P(s) s/σ² · exp(−(ρ − s)²/2σ²) · [e^(−ρs/σ²) I0(ρs/σ²)] ds.
  table_.resize(points);
  for (std::size_t i = 0; i < points; ++i) {
    const double rho = static_cast<double>(i) * step_mm_;
    double sum = 0;
    for (std::size_t k = 0; k < s.size(); ++k) {
      const double d = rho - s[k];
      sum += weight[k] * std::exp(-d * d / (2 * s2)) * scaled_bessel_i0(rho * s[k] / s2);
    }
    table_[i] = sum / s2;
  }
}

double RadialPressure::at(double distance_mm) const {
  if (!(distance_mm <= support_mm_)) return 0.0;
  if (table_.empty()) return press_.pressure_at_N_per_mm2(distance_mm);
  const double u = distance_mm / step_mm_;
  const auto i = std::min(static_cast<std::size_t>(u), table_.size() - 2);
  const double f = u - static_cast<double>(i);
  return (1 - f) * table_[i] + f * table_[i + 1];
}

}  // namespace emit
