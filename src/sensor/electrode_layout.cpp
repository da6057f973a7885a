#include "emit/sensor/electrode_layout.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numeric>

#include "emit/core/errors.hpp"

namespace emit {

namespace {

std::string mm(double value) {
  char text[32];
  std::snprintf(text, sizeof text, "%.3g mm", value);
  return text;
}

Electrode electrode_at(const Border& border, double s_mm, double width_mm) {
  Electrode e;
  e.center_s_mm = wrap_arclength(s_mm, border.length_mm());
  e.center_mm = border.point_at(e.center_s_mm);
  e.width_mm = width_mm;
  return e;
}

}  // namespace

std::vector<Electrode> default_electrode_layout(const Shape& shape, const Border& border, int count, double width_mm) {
  if (count < 3) throw InvalidInput("electrodes.count: at least 3 electrodes are needed, got " + std::to_string(count));
  std::vector<Electrode> electrodes;
  if (shape.kind == ShapeKind::rectangle) {
    if (count % 4 != 0)
      throw InvalidInput(
          "electrodes.count: the default layout puts count/4 electrodes on each side of a "
          "rectangle, so count must be a multiple of 4 (got " +
          std::to_string(count) + "); give an explicit list for other layouts");
    const int per_side = count / 4;
    const double w = shape.width_mm, h = shape.height_mm;
    const double side_start[4] = {0, w, w + h, 2 * w + h};
    const double side_length[4] = {w, h, w, h};
    for (int side = 0; side < 4; ++side)
      for (int i = 0; i < per_side; ++i)
        electrodes.push_back(
            electrode_at(border, side_start[side] + (i + 0.5) * side_length[side] / per_side, width_mm));
    return electrodes;
  }
  const double spacing = border.length_mm() / count;
  // A circle's (and a cap's rim's) first electrode at angle 0, as README "Sensor description" says.
  const bool round = shape.kind == ShapeKind::circle || shape.kind == ShapeKind::spherical_cap;
  const double offset = round ? 0.0 : 0.5 * spacing;
  for (int i = 0; i < count; ++i) electrodes.push_back(electrode_at(border, offset + i * spacing, width_mm));
  return electrodes;
}

std::vector<Electrode> place_electrodes(const Border& border, const std::vector<Vector2>& centers_mm,
                                        const std::vector<double>& widths_mm) {
  const double tolerance_mm = std::max(0.01, 1e-4 * border.size_mm());
  std::vector<Electrode> electrodes;
  for (std::size_t i = 0; i < centers_mm.size(); ++i) {
    const auto projection = border.project(centers_mm[i]);
    if (projection.distance_mm > tolerance_mm)
      throw InvalidInput("electrodes[" + std::to_string(i) + "]: centre (" + mm(centers_mm[i].x()) + ", " +
                         mm(centers_mm[i].y()) + ") is " + mm(projection.distance_mm) + " off the border (tolerance " +
                         mm(tolerance_mm) + ")");
    electrodes.push_back(electrode_at(border, projection.s_mm, widths_mm[i]));
  }
  return electrodes;
}

void validate_electrodes(const Border& border, const std::vector<Electrode>& electrodes) {
  const int n = static_cast<int>(electrodes.size());
  if (n < 3) throw InvalidInput("electrodes: at least 3 electrodes are needed, got " + std::to_string(n));
  for (int i = 0; i < n; ++i)
    if (!(electrodes[i].width_mm > 0) || !std::isfinite(electrodes[i].width_mm))
      throw InvalidInput("electrodes[" + std::to_string(i) + "].width_mm: must be positive, got " +
                         std::to_string(electrodes[i].width_mm));
  for (int i = 0; i < n; ++i)
    if (electrodes[i].width_mm >= border.length_mm())
      throw InvalidInput("electrodes[" + std::to_string(i) + "].width_mm: " + mm(electrodes[i].width_mm) +
                         " is longer than the whole border (" + mm(border.length_mm()) + ")");
  std::vector<int> order(n);
  std::iota(order.begin(), order.end(), 0);
  std::sort(order.begin(), order.end(),
            [&](int a, int b) { return electrodes[a].center_s_mm < electrodes[b].center_s_mm; });
  const double length = border.length_mm();
  for (int k = 0; k < n; ++k) {
    const Electrode& a = electrodes[order[k]];
    const Electrode& b = electrodes[order[(k + 1) % n]];
    double centre_gap = b.center_s_mm - a.center_s_mm;
    if (k == n - 1) centre_gap += length;
    const double gap = centre_gap - 0.5 * (a.width_mm + b.width_mm);
    if (gap <= 1e-9 * length) {
      const std::string what = gap < 0 ? "overlap by " + mm(-gap) : "touch (no insulating gap)";
      throw InvalidInput("electrodes[" + std::to_string(order[k]) + "] and electrodes[" +
                         std::to_string(order[(k + 1) % n]) + "]: " + what);
    }
  }
}

}  // namespace emit
