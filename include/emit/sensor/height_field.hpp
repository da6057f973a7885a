#pragma once
/// \file height_field.hpp
/// A sheet's surface read from a file (README "Sensor description", shape "mesh"), as triangles
/// that +z sees once: its chart is (x, y), and above each chart point it has one height, normal
/// and slope (sensor/surface.hpp). A fingertip's pad, a dome or any skin that faces one way is
/// one; a surface that folds over itself, or has a triangle seen edge-on, is refused.
///
/// Lookups go through a uniform grid of triangle lists over the (x, y) box, built once; they
/// allocate nothing, so the per-frame fit may call them.
#include <optional>
#include <string>
#include <vector>

#include "emit/core/types.hpp"
#include "emit/sensor/border.hpp"

namespace emit {

class HeightField {
 public:
  using Nodes = Eigen::Matrix<double, Eigen::Dynamic, 3, Eigen::RowMajor>;
  using Triangles = Eigen::Matrix<int, Eigen::Dynamic, 3, Eigen::RowMajor>;

  /// \throw InvalidInput naming `context` when a triangle is steeper than 89° seen from +z, or
  /// when the surface covers a point twice seen from +z.
  HeightField(Nodes nodes_mm, Triangles triangles, const std::string& context);

  /// The surface's point above chart point c = (x, y); beyond the surface's border, (x, y) at
  /// the height of the border's nearest point (a continuation for discs that reach past it).
  Vector3 point_mm(const Vector2& chart_mm) const;
  /// The unit normal there, on the +z side (the triangle's: piecewise constant).
  Vector3 normal(const Vector2& chart_mm) const;
  /// ∂P/∂c there: (1, 0, ∂z/∂x) and (0, 1, ∂z/∂y), the triangle's slopes.
  Eigen::Matrix<double, 3, 2> tangents(const Vector2& chart_mm) const;

  double area_mm2() const { return area_mm2_; }
  /// Whether any node is off the plane z = 0.
  bool is_curved() const { return curved_; }
  /// The border seen from +z, as a polygon through its border nodes (x, y), when it is one loop
  /// (none for a surface with holes): where press scripts keep their margin (twin/press_scripts).
  const std::optional<Border>& outline() const { return outline_; }
  const Nodes& nodes_mm() const { return nodes_mm_; }
  const Triangles& triangles() const { return triangles_; }

 private:
  /// The triangle that holds c seen from +z, else the nearest one; and the barycentric
  /// coordinates in it of c, or of its point nearest c.
  Index locate(const Vector2& c, Vector3& weights) const;
  /// c's barycentric coordinates in triangle t seen from +z.
  Vector3 barycentric(Index t, const Vector2& c) const;
  Vector2 nearest_on_triangle(Index t, const Vector2& c) const;
  Vector3 centroid_mm(Index t) const;
  Eigen::Vector2i cell_of(const Vector2& c) const;

  Nodes nodes_mm_;
  Triangles triangles_;
  Eigen::AlignedBox2d box_;
  double cell_mm_ = 1;
  Eigen::Vector2i cells_{1, 1};
  std::vector<int> cell_start_, cell_triangles_;  ///< per grid cell (row-major), the triangles over it
  double area_mm2_ = 0;
  bool curved_ = false;
  std::optional<Border> outline_;
};

/// A surface's border edges (each used by one triangle) chained into one loop of nodes, in the
/// order they follow each other; none if they make several loops or do not close.
std::optional<std::vector<int>> border_loop(const HeightField::Triangles& triangles);

}  // namespace emit
