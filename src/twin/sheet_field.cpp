#include "emit/twin/sheet_field.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <random>

#include "emit/core/errors.hpp"

namespace emit {

namespace {

/// The border's bounding box, from points along it.
Eigen::AlignedBox2d bounding_box(const Border& border) {
  Eigen::AlignedBox2d box;
  for (int k = 0; k < 512; ++k) box.extend(border.point_at(border.length_mm() * k / 512));
  return box;
}

/// Points of the sheet on a grid over its bounding box, for the field's range.
std::vector<Vector2> sample_points(const Border& border) {
  const Eigen::AlignedBox2d box = bounding_box(border);
  std::vector<Vector2> points;
  constexpr int n = 96;
  for (int i = 0; i <= n; ++i)
    for (int j = 0; j <= n; ++j) {
      const Vector2 p = box.min() + Vector2(box.sizes().x() * i / n, box.sizes().y() * j / n);
      if (border.contains(p)) points.push_back(p);
    }
  return points;
}

}  // namespace

SheetField::SheetField(const Border& border, double amplitude, std::uint64_t seed, int modes) {
  if (!(amplitude >= 0 && amplitude < 1)) throw InvalidInput("sheet field amplitude must be in [0, 1)");
  if (modes < 1) throw InvalidInput("sheet field needs at least one mode");
  if (amplitude == 0) return;
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  const double size_mm = bounding_box(border).sizes().maxCoeff();
  for (int k = 0; k < modes; ++k) {
    // Wavelength from half to twice the sheet's size: smooth over the sheet, never a ripple.
    const double wavelength_mm = size_mm * (0.5 + 1.5 * unit(rng));
    const double angle = 2 * std::numbers::pi * unit(rng);
    const Vector2 direction(std::cos(angle), std::sin(angle));
    modes_.push_back(
        {(2 * std::numbers::pi / wavelength_mm) * direction, 2 * std::numbers::pi * unit(rng), 0.5 + 0.5 * unit(rng)});
  }
  // Scale the sum so that its largest |f| over the sheet is log(1 + amplitude).
  const std::vector<Vector2> points = sample_points(border);
  double largest = 0;
  for (const Vector2& p : points) largest = std::max(largest, std::abs(log_factor(p)));
  if (largest == 0) throw InvalidInput("sheet field: the sheet has no area");
  const double scale = std::log1p(amplitude) / largest;
  for (Mode& m : modes_) m.weight *= scale;
  min_factor_ = max_factor_ = factor(points.front());
  for (const Vector2& p : points) {
    min_factor_ = std::min(min_factor_, factor(p));
    max_factor_ = std::max(max_factor_, factor(p));
  }
}

double SheetField::log_factor(const Vector2& p_mm) const {
  double f = 0;  // Σ w_k cos(k·p + φ_k)
  for (const Mode& m : modes_) f += m.weight * std::cos(m.wavevector_per_mm.dot(p_mm) + m.phase);
  return f;
}

double SheetField::factor(const Vector2& p_mm) const { return std::exp(log_factor(p_mm)); }

}  // namespace emit
