#include "emit/sensor/electrode_layout.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <numeric>

#include "emit/core/errors.hpp"
#include "emit/sensor/surface.hpp"

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
  if (is_sleeve(shape)) {
    // Its border is the two rims u = L (θ rising along it) and u = 0 (θ falling), the seam edges
    // between them. Each rim is a rectangle's side: count/2 electrodes centred in equal divisions
    // of it from the seam, so none meets the seam (θ = ±180°) and they are symmetric about +z.
    if (count % 2 != 0)
      throw InvalidInput(
          "electrodes.count: the default layout puts count/2 electrodes on each rim of a sleeve, so "
          "count must be even (got " +
          std::to_string(count) + "); give an explicit list for other layouts");
    const int per_rim = count / 2;
    const double L = shape.length_mm, round = 2 * std::numbers::pi * shape.radius_mm;
    for (const double rim_start : {L, 2 * L + round})
      // Numbered along the border from the electrode at θ = 0, or (count/2 even) the first past it.
      for (int k = 0; k < per_rim; ++k)
        electrodes.push_back(
            electrode_at(border, rim_start + ((k + per_rim / 2) % per_rim + 0.5) * round / per_rim, width_mm));
    return electrodes;
  }
  if (shape.kind == ShapeKind::rectangle || shape.kind == ShapeKind::cylinder) {
    if (count % 4 != 0)
      throw InvalidInput(
          "electrodes.count: the default layout puts count/4 electrodes on each side of a "
          "rectangle, so count must be a multiple of 4 (got " +
          std::to_string(count) + "); give an explicit list for other layouts");
    const int per_side = count / 4;
    // A cylinder patch's chart is the rectangle L × Rα (sensor/surface.hpp).
    const bool patch = shape.kind == ShapeKind::cylinder;
    const double w = patch ? shape.length_mm : shape.width_mm;
    const double h = patch ? shape.radius_mm * shape.angle_deg * std::numbers::pi / 180 : shape.height_mm;
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

double border_tolerance_mm(const Border& border) { return std::max(0.01, 1e-4 * border.size_mm()); }

std::vector<Electrode> place_electrodes(const Border& border, const std::vector<Vector2>& centers_mm,
                                        const std::vector<double>& widths_mm) {
  const double tolerance_mm = border_tolerance_mm(border);
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

void validate_sleeve_electrodes(const Shape& shape, const Border& border, const std::vector<Electrode>& electrodes) {
  if (!is_sleeve(shape)) return;
  const double L = shape.length_mm, round = 2 * std::numbers::pi * shape.radius_mm;
  const double slack_mm = 1e-9 * border.length_mm();  // an end exactly at the seam point is on the rim
  const double rim_start[2] = {L, 2 * L + round};     // the rims u = L (x = +L/2) and u = 0 (x = −L/2)
  for (std::size_t i = 0; i < electrodes.size(); ++i) {
    const Electrode& e = electrodes[i];
    const std::string which = "electrodes[" + std::to_string(i) + "]: ";
    bool on_rim = false, centre_on_rim = false;
    for (const double start : rim_start) {
      const double from_start = wrap_arclength(e.center_s_mm - start + slack_mm, border.length_mm()) - slack_mm;
      if (from_start < -slack_mm || from_start > round + slack_mm) continue;
      centre_on_rim = true;
      on_rim = from_start - 0.5 * e.width_mm >= -slack_mm && from_start + 0.5 * e.width_mm <= round + slack_mm;
    }
    if (!centre_on_rim)
      throw InvalidInput(which +
                         "lies on the sleeve's seam (angle 180 deg between its rims), not on a rim; a sleeve's "
                         "electrodes go on its rims, x = -L/2 or L/2");
    if (!on_rim)
      throw InvalidInput(which + "crosses its rim's seam point (angle 180 deg): " + mm(e.width_mm) +
                         " wide, it must lie wholly within (-180, 180) deg");
  }
}

}  // namespace emit
