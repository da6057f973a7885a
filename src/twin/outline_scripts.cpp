#include "emit/twin/outline_scripts.hpp"

#include <cmath>
#include <numbers>
#include <random>

#include "emit/core/errors.hpp"
#include "emit/sensor/press_outline.hpp"
#include "emit/sensor/surface.hpp"

namespace emit {

const std::vector<OutlineFamily>& outline_families() {
  static const std::vector<OutlineFamily> families{OutlineFamily::bar_30x3,      OutlineFamily::bar_20x6,
                                                   OutlineFamily::ellipse_24x12, OutlineFamily::ring_12_18,
                                                   OutlineFamily::disc_r12,      OutlineFamily::l_20x4,
                                                   OutlineFamily::parallel_bars, OutlineFamily::stylus_r2};
  return families;
}

const char* outline_family_name(OutlineFamily family) {
  switch (family) {
    case OutlineFamily::bar_30x3: return "bar 30x3";
    case OutlineFamily::bar_20x6: return "bar 20x6";
    case OutlineFamily::ellipse_24x12: return "ellipse 24x12";
    case OutlineFamily::ring_12_18: return "ring 12-18";
    case OutlineFamily::disc_r12: return "disc r12";
    case OutlineFamily::l_20x4: return "L 20x4";
    case OutlineFamily::parallel_bars: return "two bars 20x3";
    case OutlineFamily::stylus_r2: return "stylus r2";
  }
  return "?";
}

namespace {

Vector2 turned(const Vector2& v, double angle_deg) {
  const double a = angle_deg * std::numbers::pi / 180;
  return {std::cos(a) * v.x() - std::sin(a) * v.y(), std::sin(a) * v.x() + std::cos(a) * v.y()};
}

}  // namespace

std::vector<Press> outline_presses(OutlineFamily family, const Vector2& centre_mm, double angle_deg, double force_N) {
  switch (family) {
    case OutlineFamily::bar_30x3: return {bar_press(centre_mm, 30, 3, angle_deg, force_N)};
    case OutlineFamily::bar_20x6: return {bar_press(centre_mm, 20, 6, angle_deg, force_N)};
    case OutlineFamily::ellipse_24x12: return {ellipse_press(centre_mm, 12, 6, angle_deg, force_N)};
    case OutlineFamily::ring_12_18: return {ring_press(centre_mm, 6, 9, force_N)};
    case OutlineFamily::disc_r12: return {Press{centre_mm.x(), centre_mm.y(), 12, force_N}};
    case OutlineFamily::stylus_r2: return {Press{centre_mm.x(), centre_mm.y(), 2, force_N}};
    case OutlineFamily::l_20x4: {
      // Legs along +x and +y from the corner, the bounding box's centre (10, 10) on the centre.
      std::vector<Vector2> l;
      for (const Vector2& v :
           {Vector2(0, 0), Vector2(20, 0), Vector2(20, 4), Vector2(4, 4), Vector2(4, 20), Vector2(0, 20)})
        l.push_back(turned(v - Vector2(10, 10), angle_deg));
      return {polygon_press(centre_mm, {l}, force_N)};
    }
    case OutlineFamily::parallel_bars: {
      const Vector2 offset = turned({0, 5}, angle_deg);
      return {bar_press(centre_mm + offset, 20, 3, angle_deg, force_N / 2),
              bar_press(centre_mm - offset, 20, 3, angle_deg, force_N / 2)};
    }
  }
  return {};
}

PressSequence outline_script(const Sensor& sensor, OutlineFamily family, int frames, const OutlineStyle& style) {
  if (is_curved(sensor.shape)) throw InvalidInput("outline presses need a flat sheet");
  if (style.min_force_N < 0 || style.max_force_N < style.min_force_N)
    throw InvalidInput("outline press forces must satisfy 0 <= min <= max");
  const Border& border = sheet_outline(sensor);
  Eigen::AlignedBox2d box;
  for (int k = 0; k < 512; ++k) box.extend(border.point_at(border.length_mm() * k / 512));
  std::mt19937_64 rng(style.seed);
  const auto uniform = [&](double a, double b) { return std::uniform_real_distribution<double>(a, b)(rng); };
  const auto keeps_margin = [&](const Vector2& p) {
    return chart_distance_to_border_mm(sensor.shape, border, p) >= style.margin_mm;
  };
  PressSequence sequence;
  for (int f = 0; f < frames; ++f) {
    bool placed = false;
    for (int attempt = 0; attempt < 100000 && !placed; ++attempt) {
      const Vector2 centre(uniform(box.min().x(), box.max().x()), uniform(box.min().y(), box.max().y()));
      const double angle_deg = uniform(0, 180);
      const double force_N =
          style.min_force_N == style.max_force_N ? style.min_force_N : uniform(style.min_force_N, style.max_force_N);
      std::vector<Press> presses = outline_presses(family, centre, angle_deg, force_N);
      placed = true;
      for (const Press& p : presses) {
        if (p.outline_mm.empty()) {
          for (int k = 0; k < 64 && placed; ++k) {
            const double t = 2 * std::numbers::pi * k / 64;
            placed = keeps_margin(Vector2(p.x_mm, p.y_mm) + p.radius_mm * Vector2(std::cos(t), std::sin(t)));
          }
        }
        for (const auto& polygon : placed_outline_mm(p))
          for (const Vector2& v : polygon) placed = placed && keeps_margin(v);
      }
      if (placed) sequence.push_back(std::move(presses));
    }
    if (!placed)
      throw InvalidInput(std::string("no room on the sheet for a ") + outline_family_name(family) + " " +
                         std::to_string(style.margin_mm) + " mm from the border");
  }
  return sequence;
}

}  // namespace emit
