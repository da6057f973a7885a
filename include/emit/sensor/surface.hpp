#pragma once
/// \file surface.hpp
/// The sheet as a surface in 3D, named by a chart: 2D coordinates (mm) of its points in which its
/// border, electrodes and meshing are those of a flat sheet (sensor/border.hpp).
///   - A flat sheet is its shape in the plane z = 0; its chart is (x, y).
///   - A spherical cap (README "Sensor description") is the part of the sphere of radius R centred
///     at (0, 0, −√(R² − a²)) above the plane z = 0: its rim is the circle of radius a there, its
///     apex at z = R − √(R² − a²). Seen from +z the cap covers the disc of radius a once, so its
///     chart is (x, y) too, and its border the rim's circle (arc lengths unchanged).
///   - A cylinder patch of radius R, length L and angle α about the x axis is unrolled: the chart
///     (u, v) ∈ [0, L] × [0, Rα] is the point (u − L/2, R sin θ, R cos θ), θ = v/R − α/2 from +z
///     towards +y. The map keeps lengths and areas (an isometry), so the chart's rectangle is the
///     sheet's true border and the distances along it are the sheet's. A sleeve (α = 360°) is
///     periodic in v: v and v + 2πR are the same point, and its border is the two rims u = 0, L.
///   - A surface from a file, once read (Shape::surface, sensor/height_field.hpp), is seen once
///     from +z: its chart is (x, y) too, its points' heights the file's triangles'.
#include "emit/core/types.hpp"
#include "emit/sensor/border.hpp"
#include "emit/sensor/sensor.hpp"

namespace emit {

/// Whether the sheet is not flat.
bool is_curved(const Shape& shape);

/// Whether the sheet is a cylinder closed around its axis (a sleeve): its chart is periodic in v.
bool is_sleeve(const Shape& shape);

/// The point of the sheet at chart point c: (x, y, 0) on a flat sheet. For a cap, c must be
/// within the rim (a point beyond it is taken at the rim's height, 0); a cylinder's chart extends
/// beyond the patch along the same cylinder.
Vector3 surface_point_mm(const Shape& shape, const Vector2& chart_mm);

/// The chart point of the sheet's point nearest p, for p on or near the sheet (the inverse of
/// surface_point_mm on it): (x, y) on a flat sheet and a cap (the point above or below p); on a
/// cylinder, p's position along the axis and its angle about it (on a sleeve v in [0, 2πR)).
Vector2 surface_chart_mm(const Shape& shape, const Vector3& point_mm);

/// c with a sleeve's v taken into [0, 2πR) (the same point); c itself on any other sheet.
Vector2 wrapped_chart_mm(const Shape& shape, const Vector2& chart_mm);

/// How far chart point c is inside the sheet's border [mm] (negative outside it): the border's
/// distance (sensor/border.hpp) on a flat sheet, a cap or a cylinder patch, whose charts keep the
/// border's lengths; around a sleeve, whose chart's v wraps, the distance to the nearer rim.
double chart_distance_to_border_mm(const Shape& shape, const Border& border, const Vector2& chart_mm);

/// The border of the sheet's chart: the sensor's border, or a file's surface's outline seen from
/// +z (sensor/height_field.hpp). \throw InvalidInput for a mesh file read without its surface
/// or with holes.
const Border& sheet_outline(const Sensor& sensor);

/// The sheet's highest point above (x, y) seen from +z: on a cap and a flat sheet the point of
/// chart (x, y); on a cylinder the upper one, z = √(R² − y²) (y taken within ±R).
Vector3 surface_point_above_mm(const Shape& shape, const Vector2& xy_mm);

/// The sheet's unit normal at chart point c, pointing away from the sphere's centre or the
/// cylinder's axis (+z on a flat sheet).
Vector3 surface_normal(const Shape& shape, const Vector2& chart_mm);

/// ∂P/∂c (columns): how the surface point P moves with the chart's two coordinates. Flat: the
/// plane's unit vectors. On a cap z = √(R² − ρ²) − d, so ∂z/∂x = −x / √(R² − ρ²); at a
/// hemisphere's rim that is infinite, so ρ is taken at most 0.999 R there. On a cylinder the
/// columns are orthonormal: (1, 0, 0) and (0, cos θ, −sin θ).
Eigen::Matrix<double, 3, 2> surface_tangents(const Shape& shape, const Vector2& chart_mm);

/// The sheet's area [mm²]: 2πR²(1 − cos θ) for a cap (sin θ = a/R), RαL for a cylinder, a mesh
/// file's triangles' once read (0 before).
double surface_area_mm2(const Shape& shape);

}  // namespace emit
