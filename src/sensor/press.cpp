#include "emit/sensor/press.hpp"

#include <cmath>
#include <cstdio>
#include <numbers>
#include <sstream>

#include "emit/core/errors.hpp"

namespace emit {

double Press::pressure_N_per_mm2() const { return force_N / (std::numbers::pi * radius_mm * radius_mm); }

Press parse_press(const std::string& text) {
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
                         "\" is not a number (expected x_mm,y_mm,radius_mm,force_N)");
    values.push_back(value);
  }
  if (values.size() != 4)
    throw InvalidInput("press \"" + text + "\": expected 4 values x_mm,y_mm,radius_mm,force_N, got " +
                       std::to_string(values.size()));
  return Press{values[0], values[1], values[2], values[3]};
}

void validate_press(const Sensor& sensor, const Press& press, const std::string& where) {
  char position[96];
  std::snprintf(position, sizeof position, "(%g, %g) mm", press.x_mm, press.y_mm);
  if (!std::isfinite(press.x_mm) || !std::isfinite(press.y_mm) || !std::isfinite(press.radius_mm) ||
      !std::isfinite(press.force_N))
    throw InvalidInput(where + ": values must be finite numbers");
  if (!(press.radius_mm > 0)) throw InvalidInput(where + ": radius must be positive");
  if (press.force_N < 0) throw InvalidInput(where + ": force must not be negative");
  if (sensor.border && !sensor.border->contains(Vector2(press.x_mm, press.y_mm)))
    throw InvalidInput(where + ": centre " + position + " is off the sheet");
}

}  // namespace emit
