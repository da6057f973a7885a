#pragma once
/// \file electrode_layout.hpp
/// Where the electrodes go: the default layout rule (README, "Sensor description") and the checks every layout passes.
#include <vector>

#include "emit/sensor/sensor.hpp"

namespace emit {

/// The default rule: a rectangle gets count/4 electrodes per side, centred in equal divisions of
/// the side, numbered counter-clockwise from the bottom side's leftmost; a circle gets them evenly
/// spaced with electrode 0 at angle 0; a polygon evenly spaced by arc length, electrode 0 centred
/// half a spacing after points[0].
/// \throw InvalidInput if count < 3, or a rectangle's count is not a multiple of 4.
std::vector<Electrode> default_electrode_layout(const Shape& shape, const Border& border, int count, double width_mm);

/// Electrodes from explicit centres: each centre is projected on the border.
/// \throw InvalidInput ("electrodes[i]: …") if a centre is off the border by more than
/// max(0.01 mm, 1e-4 × sheet size).
std::vector<Electrode> place_electrodes(const Border& border, const std::vector<Vector2>& centers_mm,
                                        const std::vector<double>& widths_mm);

/// Checks a layout: at least 3 electrodes, positive widths, no two electrodes overlapping or
/// touching (an insulating gap must separate them). \throw InvalidInput naming the electrodes.
void validate_electrodes(const Border& border, const std::vector<Electrode>& electrodes);

}  // namespace emit
