#include "emit/twin/calibration_person.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <random>
#include <string>

#include "emit/core/errors.hpp"
#include "emit/core/option_check.hpp"
#include "emit/sensor/surface.hpp"

namespace emit {

void CalibrationPersonOptions::validate() const {
  const char* owner = "CalibrationPersonOptions";
  option_check::at_least(owner, "presses", presses, 0);
  option_check::non_negative(owner, "quiet_s", quiet_s);
  option_check::positive(owner, "min_hold_s", min_hold_s);
  option_check::within(owner, "max_hold_s", max_hold_s, min_hold_s, 1e6);
  option_check::positive(owner, "lift_s", lift_s);
  option_check::non_negative(owner, "min_force_N", min_force_N);
  option_check::within(owner, "max_force_N", max_force_N, min_force_N, 1e6);
  option_check::positive(owner, "radius_mm", radius_mm);
  option_check::positive(owner, "weight_radius_mm", weight_radius_mm);
  option_check::non_negative(owner, "margin_mm", margin_mm);
  for (const double weight : weights_N) option_check::positive(owner, "weights_N", weight);
  if (presses == 0 && weights_N.empty())
    option_check::fail(owner, "presses", "positive when there are no weights", "0");
}

CalibrationPerson::CalibrationPerson(const Sensor& sensor, const CalibrationPersonOptions& options) {
  options.validate();
  const Border& border = sheet_outline(sensor);
  Eigen::AlignedBox2d box;
  for (int k = 0; k < 512; ++k) box.extend(border.point_at(border.length_mm() * k / 512));
  std::mt19937_64 rng(options.seed);
  const auto uniform = [&](double a, double b) { return std::uniform_real_distribution<double>(a, b)(rng); };
  const auto room = [&](const Vector2& p, double radius_mm) {
    return chart_distance_to_border_mm(sensor.shape, border, p) >= radius_mm + options.margin_mm;
  };
  // A point with room in cell (i, j) of a k × k grid over the box the centres may reach (the
  // sheet's, less the radius and the margin); else anywhere on the sheet.
  const auto place = [&](int cell, int k, double radius_mm) -> Vector2 {
    const Vector2 inset = Vector2::Constant(std::min(radius_mm + options.margin_mm, 0.49 * box.sizes().minCoeff()));
    const Vector2 size = (box.sizes() - 2 * inset) / k;
    const int column = cell % k, row = cell / k;  // the cell's place in the grid
    const Vector2 corner = box.min() + inset + Vector2(column * size.x(), row * size.y());
    for (int attempt = 0; attempt < 50; ++attempt) {
      Vector2 p = corner + Vector2(uniform(0, size.x()), uniform(0, size.y()));
      if (room(p, radius_mm)) return p;
    }
    for (int attempt = 0; attempt < 100000; ++attempt) {
      Vector2 p(uniform(box.min().x(), box.max().x()), uniform(box.min().y(), box.max().y()));
      if (room(p, radius_mm)) return p;
    }
    throw InvalidInput("calibration script: no room on the sheet for a press of radius " + std::to_string(radius_mm) +
                       " mm " + std::to_string(options.margin_mm) + " mm from its border");
  };
  // The finger presses cover the sheet: one in each cell of a k × k grid (k² ≥ presses), the
  // cells in random order, so that any first n of them are spread over it too.
  const int k = std::max(1, static_cast<int>(std::ceil(std::sqrt(static_cast<double>(options.presses)))));
  std::vector<int> cells(static_cast<std::size_t>(k * k));
  std::iota(cells.begin(), cells.end(), 0);
  std::shuffle(cells.begin(), cells.end(), rng);
  double t = options.quiet_s;
  const auto add = [&](const Press& press, bool weight) {
    const double hold_s = uniform(options.min_hold_s, options.max_hold_s);
    presses_.push_back({t, t + hold_s, press, weight});
    t += hold_s + options.lift_s;
  };
  for (int i = 0; i < options.presses; ++i) {
    const Vector2 p = place(cells[static_cast<std::size_t>(i % (k * k))], k, options.radius_mm);
    add(press_at_chart(sensor.shape, p, options.radius_mm, uniform(options.min_force_N, options.max_force_N)), false);
  }
  for (const double weight_N : options.weights_N) {
    const Vector2 p = place(static_cast<int>(uniform(0, k * k - 1e-9)), k, options.weight_radius_mm);
    add(press_at_chart(sensor.shape, p, options.weight_radius_mm, weight_N), true);
  }
  duration_s_ = t;
}

const Press* CalibrationPerson::press_at(double t_s) const {
  // The first press that ends after t (the presses are in time order and do not overlap).
  const auto it = std::upper_bound(presses_.begin(), presses_.end(), t_s,
                                   [](double t, const PersonPress& p) { return t < p.end_s; });
  return it != presses_.end() && t_s >= it->start_s ? &it->press : nullptr;
}

PressSequence CalibrationPerson::frames(double frames_per_s) const {
  option_check::positive("CalibrationPerson::frames", "frames_per_s", frames_per_s);
  const auto count = static_cast<std::size_t>(std::ceil(duration_s_ * frames_per_s));
  PressSequence sequence(count);
  for (std::size_t f = 0; f < count; ++f)
    if (const Press* press = press_at(static_cast<double>(f) / frames_per_s)) sequence[f].push_back(*press);
  return sequence;
}

}  // namespace emit
