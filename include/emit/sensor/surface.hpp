#pragma once
/// \file surface.hpp
/// The sheet as a surface in 3D. A flat sheet is its shape in the plane z = 0. A spherical cap
/// (README "Sensor description") is the part of the sphere of radius R centred at (0, 0, −√(R² − a²))
/// above the plane z = 0: its rim is the circle of radius a there, its apex at z = R − √(R² − a²).
/// Seen from +z the cap covers the disc of radius a once, so (x, y) names a point of it, and its
/// border and electrodes are the rim's circle's (sensor/border.hpp), arc lengths unchanged.
#include "emit/core/types.hpp"
#include "emit/sensor/sensor.hpp"

namespace emit {

/// Whether the sheet is not flat.
bool is_curved(const Shape& shape);

/// The point of the sheet above (x, y): (x, y, 0) on a flat sheet. For a cap, (x, y) must be
/// within the rim (a point beyond it is taken at the rim's height, 0).
Vector3 surface_point_mm(const Shape& shape, const Vector2& xy_mm);

/// The sheet's unit normal at the point above (x, y), pointing away from the sphere's centre (+z
/// on a flat sheet).
Vector3 surface_normal(const Shape& shape, const Vector2& xy_mm);

/// ∂P/∂x and ∂P/∂y (columns) of the point P above (x, y): how the surface point moves as (x, y)
/// does. Flat: the plane's unit vectors. On a cap z = √(R² − ρ²) − d, so ∂z/∂x = −x / √(R² − ρ²);
/// at a hemisphere's rim that is infinite, so ρ is taken at most 0.999 R there.
Eigen::Matrix<double, 3, 2> surface_tangents(const Shape& shape, const Vector2& xy_mm);

/// The sheet's area [mm²]: 2πR²(1 − cos θ) for a cap (sin θ = a/R); 0 for a mesh file.
double surface_area_mm2(const Shape& shape);

}  // namespace emit
