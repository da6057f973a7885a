#include "emit/sensor/press.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <sstream>

#include "emit/core/errors.hpp"
#include "emit/core/quote_input.hpp"
#include "emit/sensor/press_outline.hpp"
#include "emit/sensor/surface.hpp"

namespace emit {

double Press::pressure_N_per_mm2() const {
  if (!outline_mm.empty()) return force_N / press_area_mm2(*this);
  return force_N / (std::numbers::pi * radius_mm * radius_mm);
}

double Press::pressure_at_N_per_mm2(double distance_mm) const {
  if (!(distance_mm <= radius_mm)) return 0.0;
  if (profile == PressProfile::flat) return pressure_N_per_mm2();
  // Hertz: p0 = 3F/(2π a²), which integrates to F over the disc (2π p0 a²/3).
  const double s = distance_mm / radius_mm;
  return 1.5 * pressure_N_per_mm2() * std::sqrt(std::max(0.0, 1.0 - s * s));
}

bool place_known(const Press& press) { return std::isfinite(press.x_mm) && std::isfinite(press.y_mm); }
bool force_known(const Press& press) { return std::isfinite(press.force_N); }

const char* profile_name(PressProfile profile) { return profile == PressProfile::flat ? "flat" : "spherical"; }

PressProfile parse_press_profile(const std::string& name) {
  if (name == "flat") return PressProfile::flat;
  if (name == "spherical") return PressProfile::spherical;
  throw InvalidInput("press profile " + quote_input(name) + " is not flat or spherical");
}

Press parse_press(const std::string& text) {
  if (text.find(':') != std::string::npos) return parse_outline_press(text);
  std::vector<double> values;
  std::stringstream in(text);
  std::string item;
  while (std::getline(in, item, ',')) {
    std::size_t used = 0;
    double value = 0;
    try {
      value = std::stod(item, &used);
    } catch (const std::exception&) {
      used = 0;
    }
    if (used == 0 || item.find_first_not_of(" \t", used) != std::string::npos)
      throw InvalidInput("press \"" + text + "\": \"" + item +
                         "\" is not a number (expected x_mm,y_mm[,z_mm],radius_mm,force_N)");
    values.push_back(value);
  }
  if (values.size() == 5) {  // with the centre's z, for a curved sheet (a cylinder needs it)
    Press press{values[0], values[1], values[3], values[4]};
    press.z_mm = values[2];
    return press;
  }
  if (values.size() != 4)
    throw InvalidInput("press \"" + text +
                       "\": expected 4 values x_mm,y_mm,radius_mm,force_N (or 5, with z_mm after y_mm), got " +
                       std::to_string(values.size()));
  return Press{values[0], values[1], values[2], values[3]};
}

Press press_at_chart(const Shape& shape, const Vector2& chart_mm, double radius_mm, double force_N,
                     PressProfile profile) {
  const Vector3 point = surface_point_mm(shape, chart_mm);
  Press press{point.x(), point.y(), radius_mm, force_N, profile};
  press.z_mm = point.z();
  return press;
}

Vector2 press_chart_mm(const Shape& shape, const Press& press) {
  return surface_chart_mm(shape, Vector3(press.x_mm, press.y_mm, press.z_mm));
}

void validate_press(const Sensor& sensor, const Press& press, const std::string& where) {
  char position[96];
  std::snprintf(position, sizeof position, "(%g, %g) mm", press.x_mm, press.y_mm);
  // A place or force not measured (both coordinates NaN; the force NaN) is calibration's alone.
  if (std::isnan(press.x_mm) && std::isnan(press.y_mm))
    throw InvalidInput(where + ": place unknown: only emit calibrate takes presses without a place");
  if (std::isnan(press.force_N))
    throw InvalidInput(where + ": force unknown: only emit calibrate takes presses without a force");
  if (!std::isfinite(press.x_mm) || !std::isfinite(press.y_mm) || !std::isfinite(press.z_mm) ||
      !std::isfinite(press.radius_mm) || !std::isfinite(press.force_N))
    throw InvalidInput(where + ": values must be finite numbers");
  if (!(press.radius_mm > 0)) throw InvalidInput(where + ": radius must be positive");
  if (press.force_N < 0) throw InvalidInput(where + ": force must not be negative");
  if (!press.outline_mm.empty()) {
    if (is_curved(sensor.shape)) throw InvalidInput(where + ": an outline press needs a flat sheet");
    if (press.profile != PressProfile::flat) throw InvalidInput(where + ": an outline press must be flat");
    validate_outline(press.outline_mm, where);
  }
  if (sensor.shape.kind == ShapeKind::cylinder) {
    // A cylinder's point is the one along the radius through the centre: one far off the surface
    // (a press given without its z lies on the axis' plane z = 0) is refused, not moved there.
    const Vector3 centre(press.x_mm, press.y_mm, press.z_mm);
    const double off_mm = (surface_point_mm(sensor.shape, press_chart_mm(sensor.shape, press)) - centre).norm();
    if (off_mm > press_surface_tolerance_mm) {
      char text[160];
      std::snprintf(text, sizeof text, ": centre (%g, %g, %g) mm is %.3g mm off the cylinder's surface (give its z)",
                    press.x_mm, press.y_mm, press.z_mm, off_mm);
      throw InvalidInput(where + text);
    }
  }
  if (sensor.border && !sensor.border->contains(press_chart_mm(sensor.shape, press)))
    throw InvalidInput(where + ": centre " + position + " is off the sheet");
}

}  // namespace emit
