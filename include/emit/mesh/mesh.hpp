#pragma once
/// \file mesh.hpp
/// A triangle mesh of the probing sheet, with each electrode an exact set of border nodes.
#include <array>
#include <vector>

#include <Eigen/Core>

#include "emit/core/types.hpp"

namespace emit {

struct Mesh {
  /// #V by 3 node positions in mm. Flat sheets have z = 0; a curved shell (dome, sleeve) need not.
  Eigen::Matrix<double, Eigen::Dynamic, 3, Eigen::RowMajor> nodes_mm;
  /// #F by 3 node indices per triangle, counter-clockwise seen from +z for flat sheets.
  Eigen::Matrix<int, Eigen::Dynamic, 3, Eigen::RowMajor> triangles;
  /// Per electrode, the sorted indices of the nodes on it (both ends included).
  std::vector<std::vector<int>> electrode_nodes;

  Index node_count() const { return nodes_mm.rows(); }
  Index triangle_count() const { return triangles.rows(); }
  int electrode_count() const { return static_cast<int>(electrode_nodes.size()); }

  /// Area of triangle t in mm² (works in 3D).
  double triangle_area_mm2(Index t) const;
  /// Centroid of triangle t.
  Vector3 triangle_centroid_mm(Index t) const;
  /// Border edges of electrode e (pairs of node indices), derived from the triangles.
  std::vector<std::array<int, 2>> electrode_edges(int e) const;
  /// Whether the point (x, y) lies on some triangle, seen from +z (flat sheets).
  bool contains_xy(const Vector2& point_mm) const;
  /// The same among the given triangles only (a neighbourhood known to hold the point if any does).
  bool contains_xy(const Vector2& point_mm, const std::vector<Index>& among) const;
  /// Whether the point lies on triangle t, seen from +z.
  bool triangle_contains_xy(Index t, const Vector2& point_mm) const;
  /// All border edges (edges used by exactly one triangle).
  std::vector<std::array<int, 2>> border_edges() const;
};

}  // namespace emit
