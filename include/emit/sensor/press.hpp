#pragma once
/// \file press.hpp
/// A press on the sheet: a flat circular indenter with uniform pressure force/(π r²) on its disc
/// (README, "Files"). Several presses in one frame add their pressures where they overlap.
#include <string>
#include <vector>

#include "emit/sensor/sensor.hpp"

namespace emit {

struct Press {
  double x_mm = 0, y_mm = 0;
  double radius_mm = 5;
  double force_N = 10;
  double pressure_N_per_mm2() const;
};

/// The presses of each frame of a sequence.
using PressSequence = std::vector<std::vector<Press>>;

/// Parse "x,y,r,F" (mm, mm, mm, N). \throw InvalidInput naming the text.
Press parse_press(const std::string& text);

/// \throw InvalidInput if a value is not finite, the radius is not positive, the force is
/// negative, or the centre is off the sheet. `where` prefixes the message.
void validate_press(const Sensor& sensor, const Press& press, const std::string& where);

}  // namespace emit
