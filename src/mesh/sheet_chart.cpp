#include "emit/mesh/sheet_chart.hpp"

#include <numbers>

#include "emit/sensor/surface.hpp"

namespace emit {

namespace {

/// A cylinder's chart rectangle (sensor/surface.hpp).
Eigen::AlignedBox2d cylinder_box(const Shape& shape) {
  return {Vector2::Zero(), Vector2(shape.length_mm, shape.radius_mm * shape.angle_deg * std::numbers::pi / 180)};
}

}  // namespace

bool chart_on_sheet(const Mesh& mesh, const Shape& shape, const Vector2& c) {
  if (shape.kind != ShapeKind::cylinder) return mesh.contains_xy(c);
  if (is_sleeve(shape)) return c.x() >= 0 && c.x() <= shape.length_mm;
  return cylinder_box(shape).contains(c);
}

bool chart_on_sheet(const Mesh& mesh, const Shape& shape, const Vector2& c, const std::vector<Index>& near_triangles) {
  return shape.kind == ShapeKind::cylinder ? chart_on_sheet(mesh, shape, c) : mesh.contains_xy(c, near_triangles);
}

Eigen::AlignedBox2d chart_box(const Mesh& mesh, const Shape& shape) {
  if (shape.kind == ShapeKind::cylinder) return cylinder_box(shape);
  return {mesh.nodes_mm.leftCols<2>().colwise().minCoeff().transpose(),
          mesh.nodes_mm.leftCols<2>().colwise().maxCoeff().transpose()};
}

}  // namespace emit
