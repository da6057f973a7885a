#pragma once
/// \file electrode_layout.hpp
/// Where the electrodes go: the default layout rule (README, "Sensor description") and the checks every layout passes.
#include <vector>

#include "emit/sensor/sensor.hpp"

namespace emit {

/// The default rule: a rectangle gets count/4 electrodes per side, centred in equal divisions of
/// the side, numbered counter-clockwise from the bottom side's leftmost; a circle gets them evenly
/// spaced with electrode 0 at angle 0; a polygon evenly spaced by arc length, electrode 0 centred
/// half a spacing after points[0]. A cylinder patch is its chart's rectangle L × Rα. A sleeve gets
/// count/2 on each rim (x = +L/2, then x = −L/2), centred in equal divisions of the rim from its
/// seam (θ = ±180°), so symmetric about +z and clear of the seam: one at θ = 0 when count/2 is
/// odd; each rim numbered along the border (θ rising on x = +L/2, falling on x = −L/2) from the
/// one at θ = 0 or, count/2 even, the first past it.
/// \throw InvalidInput if count < 3, a rectangle's or patch's count is not a multiple of 4, or a
/// sleeve's is odd.
std::vector<Electrode> default_electrode_layout(const Shape& shape, const Border& border, int count, double width_mm);

/// How far an explicit electrode's centre may be off the border: max(0.01 mm, 1e-4 × sheet size).
double border_tolerance_mm(const Border& border);

/// Electrodes from explicit centres: each centre is projected on the border.
/// \throw InvalidInput ("electrodes[i]: …") if a centre is off the border by more than
/// max(0.01 mm, 1e-4 × sheet size).
std::vector<Electrode> place_electrodes(const Border& border, const std::vector<Vector2>& centers_mm,
                                        const std::vector<double>& widths_mm);

/// Checks a layout: at least 3 electrodes, positive widths, no two electrodes overlapping or
/// touching (an insulating gap must separate them). \throw InvalidInput naming the electrodes.
void validate_electrodes(const Border& border, const std::vector<Electrode>& electrodes);

/// On a sleeve (sensor/surface.hpp), checks that every electrode lies wholly on a rim: not on the
/// seam edges v = 0, 2πR of the chart's rectangle, nor across a rim's seam point (θ = ±180°), where
/// the chart cuts it into two intervals. Nothing to check on other shapes.
/// \throw InvalidInput naming the electrode.
void validate_sleeve_electrodes(const Shape& shape, const Border& border, const std::vector<Electrode>& electrodes);

}  // namespace emit
