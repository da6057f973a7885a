#pragma once
/// \file press.hpp
/// A press on the sheet: a circular indenter of radius r, by default flat, with uniform pressure
/// force/(π r²) on its disc, or spherical, with Hertz's p(ρ) = p0·√(1 − ρ²/r²), p0 = 3F/(2π r²)
/// (README, "Files"). Several presses in one frame add their pressures where they overlap.
///
/// A flat punch of any other outline (a bar, an ellipse, a ring, an L: sensor/press_outline.hpp)
/// is a press with an `outline_mm`: uniform pressure force/area inside it, on flat sheets only.
#include <string>
#include <vector>

#include "emit/sensor/sensor.hpp"

namespace emit {

enum class PressProfile { flat, spherical };

struct Press {
  /// The centre. On a curved sheet it is the point of the surface nearest (x, y, z): on a cap the
  /// one above (x, y) (z is set from it), on a cylinder the one along the radius through (x, y, z)
  /// (press_chart_mm). On a flat sheet z = 0.
  double x_mm = 0, y_mm = 0;
  double radius_mm = 5;  ///< the contact's radius (for spherical, Hertz's a)
  double force_N = 10;
  PressProfile profile = PressProfile::flat;
  double z_mm = 0;
  /// A flat punch's outline, in mm relative to (x, y) along the sheet's x and y: closed polygons
  /// (the last vertex joins the first, either orientation), the first its boundary, any further
  /// ones holes inside it (a ring: two circles). A point is pressed when inside an odd number of
  /// them. Empty: the disc of `radius_mm`. With an outline, `radius_mm` is the outline's reach
  /// (its farthest vertex from the centre: press_outline.hpp's constructors set it) and the
  /// profile must be flat.
  std::vector<std::vector<Vector2>> outline_mm = {};
  /// The mean pressure over the contact, F/(π r²) for a disc whatever the profile, F/area for an
  /// outline.
  double pressure_N_per_mm2() const;
  /// The pressure at distance `distance_mm` from the centre (0 outside the disc). A disc's only:
  /// an outline's pressure is not radial (press_outline.hpp's press_covers says where it is).
  double pressure_at_N_per_mm2(double distance_mm) const;
};

/// A calibration press whose place or force was not measured (a finger put down anywhere, a
/// weight set down somewhere; issue: calibration without a robot) has NaN for x_mm and y_mm, or
/// for force_N. Only calibration takes such presses (calibrate/sensor_calibration.hpp fits an
/// unknown place; the contact law needs a known force); everything else validates them away.
bool place_known(const Press& press);
bool force_known(const Press& press);

/// "flat", "spherical".
const char* profile_name(PressProfile profile);
/// \throw InvalidInput naming the text and the choices.
PressProfile parse_press_profile(const std::string& name);

/// The presses of each frame of a sequence.
using PressSequence = std::vector<std::vector<Press>>;

/// Parse "x,y,r,F" (mm, mm, mm, N) or "x,y,z,r,F"; or a flat punch's outline, "bar:…",
/// "ellipse:…", "ring:…", "polygon:…" (press_outline.hpp's parse_outline_press).
/// \throw InvalidInput naming the text.
Press parse_press(const std::string& text);

/// A press centred on the sheet's point named by chart point c (sensor/surface.hpp): its x, y
/// and z are that point's.
Press press_at_chart(const Shape& shape, const Vector2& chart_mm, double radius_mm, double force_N,
                     PressProfile profile = PressProfile::flat);

/// The chart point (sensor/surface.hpp) of the sheet's point where the press is centred.
Vector2 press_chart_mm(const Shape& shape, const Press& press);

/// How far a press's centre may be from a cylinder's surface [mm] (it is then moved onto it).
inline constexpr double press_surface_tolerance_mm = 1.0;

/// \throw InvalidInput for a place or force not known ("place unknown: only emit calibrate takes
/// presses without a place"), if a value is not finite, the radius is not positive, the force is
/// negative, the centre is off the sheet, or on a cylinder more than press_surface_tolerance_mm
/// off its surface; for an outline, if the sheet is curved, the profile not flat, or the outline
/// not valid (press_outline.hpp's validate_outline). `where` prefixes the message.
void validate_press(const Sensor& sensor, const Press& press, const std::string& where);

}  // namespace emit
