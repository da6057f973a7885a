#include "emit/sensor/surface.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "emit/core/errors.hpp"

namespace emit {

namespace {

/// The height of the sphere's centre below the rim's plane: √(R² − a²).
double centre_depth_mm(const Shape& s) {
  return std::sqrt(std::max(0.0, s.sphere_radius_mm * s.sphere_radius_mm - s.radius_mm * s.radius_mm));
}

double angle_rad(const Shape& s) { return s.angle_deg * std::numbers::pi / 180; }

/// A cylinder's polar angle θ (from +z towards +y) at chart point c.
double cylinder_theta(const Shape& s, const Vector2& c) { return c.y() / s.radius_mm - angle_rad(s) / 2; }

/// A mesh file's surface once read (sensor/height_field.hpp), else null.
const HeightField* file_surface(const Shape& s) { return s.kind == ShapeKind::mesh_file ? s.surface.get() : nullptr; }

}  // namespace

bool is_curved(const Shape& shape) {
  if (const HeightField* surface = file_surface(shape)) return surface->is_curved();
  return shape.kind == ShapeKind::spherical_cap || shape.kind == ShapeKind::cylinder;
}

bool is_sleeve(const Shape& shape) { return shape.kind == ShapeKind::cylinder && shape.angle_deg >= 360; }

Vector3 surface_point_mm(const Shape& shape, const Vector2& c) {
  if (const HeightField* surface = file_surface(shape)) return surface->point_mm(c);
  switch (shape.kind) {
    case ShapeKind::spherical_cap: {
      const double R = shape.sphere_radius_mm;
      const double z = std::sqrt(std::max(0.0, R * R - c.squaredNorm())) - centre_depth_mm(shape);
      return {c.x(), c.y(), std::max(0.0, z)};
    }
    case ShapeKind::cylinder: {
      const double theta = cylinder_theta(shape, c);
      return {c.x() - shape.length_mm / 2, shape.radius_mm * std::sin(theta), shape.radius_mm * std::cos(theta)};
    }
    default: return {c.x(), c.y(), 0};
  }
}

Vector2 wrapped_chart_mm(const Shape& shape, const Vector2& c) {
  if (!is_sleeve(shape)) return c;
  const double round = 2 * std::numbers::pi * shape.radius_mm;
  return {c.x(), c.y() - round * std::floor(c.y() / round)};
}

Vector2 surface_chart_mm(const Shape& shape, const Vector3& p) {
  if (shape.kind != ShapeKind::cylinder) return p.head<2>();
  const double v = shape.radius_mm * (std::atan2(p.y(), p.z()) + angle_rad(shape) / 2);
  return wrapped_chart_mm(shape, {p.x() + shape.length_mm / 2, v});
}

double chart_distance_to_border_mm(const Shape& shape, const Border& border, const Vector2& c) {
  if (is_sleeve(shape)) return std::min(c.x(), shape.length_mm - c.x());
  const double distance = border.distance_to_border_mm(c);
  return border.contains(c) ? distance : -distance;
}

const Border& sheet_outline(const Sensor& sensor) {
  if (sensor.border) return *sensor.border;
  if (sensor.shape.surface && sensor.shape.surface->outline()) return *sensor.shape.surface->outline();
  throw InvalidInput(sensor.shape.surface ? "the sheet's surface has holes: press scripts need one border"
                                          : "a mesh file's sheet read without its surface has no border for presses");
}

Vector3 surface_point_above_mm(const Shape& shape, const Vector2& xy) {
  if (shape.kind != ShapeKind::cylinder) return surface_point_mm(shape, xy);
  const double y = std::clamp(xy.y(), -shape.radius_mm, shape.radius_mm);
  return {xy.x(), y, std::sqrt(shape.radius_mm * shape.radius_mm - y * y)};
}

Vector3 surface_normal(const Shape& shape, const Vector2& c) {
  if (const HeightField* surface = file_surface(shape)) return surface->normal(c);
  switch (shape.kind) {
    case ShapeKind::spherical_cap:
      return (surface_point_mm(shape, c) + Vector3(0, 0, centre_depth_mm(shape))).normalized();
    case ShapeKind::cylinder: {
      const double theta = cylinder_theta(shape, c);
      return {0, std::sin(theta), std::cos(theta)};
    }
    default: return Vector3::UnitZ();
  }
}

Eigen::Matrix<double, 3, 2> surface_tangents(const Shape& shape, const Vector2& c) {
  if (const HeightField* surface = file_surface(shape)) return surface->tangents(c);
  Eigen::Matrix<double, 3, 2> t;
  t << 1, 0, 0, 1, 0, 0;
  if (shape.kind == ShapeKind::spherical_cap) {
    const double R = shape.sphere_radius_mm;
    const double height = std::sqrt(std::max(R * R - c.squaredNorm(), 1e-6 * R * R));  // √(R² − ρ²), ρ ≤ 0.999 R
    t.row(2) = -c.transpose() / height;
  } else if (shape.kind == ShapeKind::cylinder) {
    const double theta = cylinder_theta(shape, c);
    t.col(1) = Vector3(0, std::cos(theta), -std::sin(theta));
  }
  return t;
}

double surface_area_mm2(const Shape& shape) {
  switch (shape.kind) {
    case ShapeKind::spherical_cap: {
      const double R = shape.sphere_radius_mm;
      return 2 * std::numbers::pi * R * (R - centre_depth_mm(shape));  // 2πR·h, h the cap's height
    }
    case ShapeKind::cylinder: return shape.radius_mm * angle_rad(shape) * shape.length_mm;
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
    case ShapeKind::mesh_file: return shape.surface ? shape.surface->area_mm2() : 0;
  }
  return 0;
}

}  // namespace emit
