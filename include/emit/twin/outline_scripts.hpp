#pragma once
/// \file outline_scripts.hpp
/// Frames of flat punches of many outlines for the twin (sensor/press_outline.hpp), the set
/// `emit eval --outlines` scores (issue 31): things a hand or a tool presses a skin with, sized
/// for the 60 mm sheet. Each frame is one family's outline (or pair of bars) at a random place,
/// wholly on the sheet at least a margin from its border, at a random angle, with a random force.
#include <cstdint>
#include <vector>

#include "emit/sensor/press.hpp"
#include "emit/sensor/sensor.hpp"

namespace emit {

enum class OutlineFamily {
  bar_30x3,       ///< a bar 30 × 3 mm (a ruler's edge)
  bar_20x6,       ///< a bar 20 × 6 mm
  ellipse_24x12,  ///< an ellipse of axes 24 and 12 mm (semi-axes 12, 6)
  ring_12_18,     ///< a ring of diameters 12 and 18 mm (a bottle's rim)
  disc_r12,       ///< a disc of radius 12 mm (a palm)
  l_20x4,         ///< an L of two 20 × 4 mm bars, joined at a corner
  parallel_bars,  ///< two parallel 20 × 3 mm bars, their centre lines 10 mm apart (a 7 mm gap)
  stylus_r2,      ///< a disc of radius 2 mm (a stylus's tip)
};

/// Every family, in the order above.
const std::vector<OutlineFamily>& outline_families();
/// "bar 30x3", "bar 20x6", "ellipse 24x12", "ring 12-18", "disc r12", "L 20x4", "two bars 20x3",
/// "stylus r2".
const char* outline_family_name(OutlineFamily family);

/// The family's presses centred (its bounding box's centre) on `centre_mm`, turned by `angle_deg`,
/// with `force_N` in all (split evenly between a pair of bars).
std::vector<Press> outline_presses(OutlineFamily family, const Vector2& centre_mm, double angle_deg, double force_N);

struct OutlineStyle {
  double min_force_N = 4, max_force_N = 16;  ///< the frame's force, uniform
  double margin_mm = 3;                      ///< least distance of any point of an outline to the border
  std::uint64_t seed = 1;
};

/// `frames` frames of `family` on a flat sheet, each at a uniform random place where the outline
/// (its polygons' vertices, a disc's rim at 64 points) keeps `margin_mm` from the border, at a
/// uniform random angle in [0°, 180°). \throw InvalidInput for a curved sheet or one without room.
PressSequence outline_script(const Sensor& sensor, OutlineFamily family, int frames, const OutlineStyle& style);

}  // namespace emit
