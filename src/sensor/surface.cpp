#include "emit/sensor/surface.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace emit {

namespace {

/// The height of the sphere's centre below the rim's plane: √(R² − a²).
double centre_depth_mm(const Shape& s) {
  return std::sqrt(std::max(0.0, s.sphere_radius_mm * s.sphere_radius_mm - s.radius_mm * s.radius_mm));
}

}  // namespace

bool is_curved(const Shape& shape) { return shape.kind == ShapeKind::spherical_cap; }

Vector3 surface_point_mm(const Shape& shape, const Vector2& xy_mm) {
  if (shape.kind != ShapeKind::spherical_cap) return {xy_mm.x(), xy_mm.y(), 0};
  const double R = shape.sphere_radius_mm;
  const double z = std::sqrt(std::max(0.0, R * R - xy_mm.squaredNorm())) - centre_depth_mm(shape);
  return {xy_mm.x(), xy_mm.y(), std::max(0.0, z)};
}

Vector3 surface_normal(const Shape& shape, const Vector2& xy_mm) {
  if (shape.kind != ShapeKind::spherical_cap) return Vector3::UnitZ();
  const Vector3 p = surface_point_mm(shape, xy_mm);
  return (p + Vector3(0, 0, centre_depth_mm(shape))).normalized();
}

Eigen::Matrix<double, 3, 2> surface_tangents(const Shape& shape, const Vector2& xy_mm) {
  Eigen::Matrix<double, 3, 2> t;
  t << 1, 0, 0, 1, 0, 0;
  if (shape.kind != ShapeKind::spherical_cap) return t;
  const double R = shape.sphere_radius_mm;
  const double height = std::sqrt(std::max(R * R - xy_mm.squaredNorm(), 1e-6 * R * R));  // √(R² − ρ²), ρ ≤ 0.999 R
  t.row(2) = -xy_mm.transpose() / height;
  return t;
}

double surface_area_mm2(const Shape& shape) {
  switch (shape.kind) {
    case ShapeKind::spherical_cap: {
      const double R = shape.sphere_radius_mm;
      return 2 * std::numbers::pi * R * (R - centre_depth_mm(shape));  // 2πR·h, h the cap's height
    }
    case ShapeKind::rectangle: return shape.width_mm * shape.height_mm;
    case ShapeKind::circle: return std::numbers::pi * shape.radius_mm * shape.radius_mm;
    case ShapeKind::polygon: {
      double twice = 0;
      for (std::size_t i = 0; i < shape.points_mm.size(); ++i) {
        const Vector2& p = shape.points_mm[i];
        const Vector2& q = shape.points_mm[(i + 1) % shape.points_mm.size()];
        twice += p.x() * q.y() - q.x() * p.y();
      }
      return std::abs(twice) / 2;
    }
    case ShapeKind::mesh_file: return 0;
  }
  return 0;
}

}  // namespace emit
