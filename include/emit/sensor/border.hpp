#pragma once
/// \file border.hpp
/// The border of a flat sheet as a closed curve parameterised by arc length s ∈ [0, length),
/// counter-clockwise. Electrodes are arc-length intervals of it (README, "Sensor description"), so a 3 mm electrode on
/// a circle is 3 mm of arc, and one that wraps a polygon corner is still one interval.
#include <vector>

#include "emit/core/types.hpp"

namespace emit {

/// One piece of the border: a straight segment or a circular arc, counter-clockwise.
struct BorderPiece {
  enum class Kind { line, arc };
  Kind kind = Kind::line;
  Vector2 start_mm{0, 0};
  Vector2 end_mm{0, 0};
  Vector2 arc_center_mm{0, 0};  ///< arcs only
  double arc_radius_mm = 0;     ///< arcs only
  double arc_start_rad = 0;     ///< arcs only: angle of start_mm about the centre
  double start_s_mm = 0;        ///< arc length of start_mm along the whole border
  double length_mm = 0;
};

class Border {
 public:
  /// Rectangle [0,w]×[0,h]; s = 0 at the bottom-left corner (the sensor description's origin).
  static Border rectangle(double width_mm, double height_mm);
  /// Circle; s = 0 at angle 0 (the +x point), as the default electrode layout numbers from there.
  static Border circle(const Vector2& center_mm, double radius_mm);
  /// Simple polygon; s = 0 at points[0]. Clockwise input is reversed (then s = 0 is still points[0]).
  /// \throw InvalidInput if fewer than 3 points, zero area, or repeated consecutive points.
  static Border polygon(const std::vector<Vector2>& points_mm);

  double length_mm() const { return length_mm_; }
  const std::vector<BorderPiece>& pieces() const { return pieces_; }

  /// Point at arc length s (taken modulo the length).
  Vector2 point_at(double s_mm) const;
  /// Nearest point of the border to p: its arc length and its distance from p.
  struct Projection {
    double s_mm;
    double distance_mm;
  };
  Projection project(const Vector2& p_mm) const;
  /// Whether p lies inside the closed curve (even-odd rule; points on the border count as inside).
  bool contains(const Vector2& p_mm) const;
  /// Signed distance-like measure: distance from p to the border (0 on it).
  double distance_to_border_mm(const Vector2& p_mm) const { return project(p_mm).distance_mm; }
  /// A length scale of the sheet (its bounding-box diagonal), for relative tolerances.
  double size_mm() const { return size_mm_; }

 private:
  std::vector<BorderPiece> pieces_;
  double length_mm_ = 0;
  double size_mm_ = 0;
  void finish();
};

/// s wrapped into [0, length).
double wrap_arclength(double s_mm, double length_mm);

}  // namespace emit
