#include "emit/model/force_law.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>

#include "emit/core/option_check.hpp"

namespace emit {

double ImageForceLaw::force_N(double integral_V_mm2) const {
  if (!(integral_V_mm2 > 0)) return 0.0;
  return std::pow(std::max(b1_V_mm2 / integral_V_mm2 + b2, 1e-12), b3);
}

double ImageForceLaw::indenter_area_mm2() const { return std::numbers::pi * indenter_radius_mm * indenter_radius_mm; }

double ImageForceLaw::force_relative_std() const {
  return std::hypot(log_std, (1 + b3) * unknown_indenter_log_area_std);
}

double ImageForceLaw::pressure_relative_std() const { return std::hypot(log_std, b3 * unknown_indenter_log_area_std); }

void ImageForceLaw::validate() const {
  option_check::non_negative("ImageForceLaw", "b1_V_mm2", b1_V_mm2);
  if (!std::isfinite(b2)) option_check::fail("ImageForceLaw", "b2", "a finite number", std::to_string(b2));
  if (!(b3 < 0 && std::isfinite(b3)))
    option_check::fail("ImageForceLaw", "b3", "negative (the force grows with the image)", std::to_string(b3));
  option_check::non_negative("ImageForceLaw", "log_std", log_std);
  option_check::positive("ImageForceLaw", "indenter_radius_mm", indenter_radius_mm);
}

}  // namespace emit
