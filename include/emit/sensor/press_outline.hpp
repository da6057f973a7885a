#pragma once
/// \file press_outline.hpp
/// Flat punches of any outline (sensor/press.hpp's Press::outline_mm): a bar, an ellipse, a ring,
/// any simple polygon (an L), with uniform pressure force/area inside. What the twin presses with
/// (twin/press_contact.hpp) and what the evaluation scores a pressed region against
/// (eval/outline_scoring.hpp): the outline's area, centroid and second moments, exact for its
/// polygons, and whether a point of a flat sheet is inside it.
///
/// Curves are polygons of `outline_curve_vertices` vertices: a circle's polygon is short of its
/// area by 2π²/(3n²) (4·10⁻⁴ for 128), and every figure here is the polygon's, so the twin and
/// the scoring agree exactly on what was pressed.
#include <string>
#include <vector>

#include "emit/core/types.hpp"
#include "emit/sensor/press.hpp"

namespace emit {

/// The vertices of an ellipse's or a circle's polygon.
inline constexpr int outline_curve_vertices = 128;

/// A bar `length_mm` × `width_mm` centred on `centre_mm`, its length at `angle_deg` from the x axis
/// (counter-clockwise). \throw InvalidInput for a size that is not positive and finite.
Press bar_press(const Vector2& centre_mm, double length_mm, double width_mm, double angle_deg, double force_N);
/// An ellipse of semi-axes a (at `angle_deg` from the x axis) and b. \throw InvalidInput as bar_press.
Press ellipse_press(const Vector2& centre_mm, double a_mm, double b_mm, double angle_deg, double force_N);
/// A ring (an annulus) between radii `inner_mm` < `outer_mm`. \throw InvalidInput unless 0 < inner < outer.
Press ring_press(const Vector2& centre_mm, double inner_mm, double outer_mm, double force_N);
/// A simple polygon, its vertices relative to `centre_mm` (the press's x, y), optionally with
/// holes. \throw InvalidInput as validate_outline.
Press polygon_press(const Vector2& centre_mm, std::vector<std::vector<Vector2>> outline_mm, double force_N);

/// "bar:x,y,length,width,angle_deg,F", "ellipse:x,y,a,b,angle_deg,F" (semi-axes),
/// "ring:x,y,inner_r,outer_r,F", "polygon:x,y,F,u1,v1,u2,v2,u3,v3[,…]" (vertices relative to
/// (x, y)); mm, degrees, N. \throw InvalidInput naming the text and what it expected.
Press parse_outline_press(const std::string& text);

/// \throw InvalidInput (`where` prefixing) unless every polygon has 3 or more finite vertices and
/// the pressed area is positive.
void validate_outline(const std::vector<std::vector<Vector2>>& outline_mm, const std::string& where);

/// The pressed area [mm²]: π r² for a disc, the boundary's polygon less its holes for an outline.
double press_area_mm2(const Press& press);
/// The pressed area's centroid in the sheet's x, y [mm] (the centre for a disc).
Vector2 press_centroid_mm(const Press& press);
/// The pressed area's second central moments per unit area [mm²], ∫ (p − c)(p − c)ᵀ dA / A:
/// r²/4 · I for a disc; a bar L × W along x gives diag(L²/12, W²/12).
Eigen::Matrix2d press_second_moments_mm2(const Press& press);

/// Whether the point (x, y) of a flat sheet is pressed by `press` (on a disc's rim: pressed).
bool press_covers(const Press& press, const Vector2& point_mm);

/// Whether `point` is inside an odd number of the polygons (each closed, vertices absolute).
bool inside_polygons(const std::vector<std::vector<Vector2>>& polygons, const Vector2& point_mm);

/// The outline's polygons moved to the press's place (vertices in the sheet's x, y).
std::vector<std::vector<Vector2>> placed_outline_mm(const Press& press);

}  // namespace emit
