#pragma once
/// \file sheet_chart.hpp
/// Where a sheet's chart (sensor/surface.hpp) names its points: a cylinder's is its unrolled
/// rectangle, every other sheet's the plane (x, y), where its mesh, seen from +z, is the sheet.
#include <Eigen/Geometry>

#include "emit/mesh/mesh.hpp"
#include "emit/sensor/sensor.hpp"

namespace emit {

/// Whether chart point c names a point of the sheet: on a cylinder, within its rectangle (any v
/// on a sleeve); otherwise on a triangle of the mesh seen from +z (Mesh::contains_xy).
bool chart_on_sheet(const Mesh& mesh, const Shape& shape, const Vector2& chart_mm);
/// The same when the point, if on the sheet, lies on one of `near_triangles` (fast: a
/// neighbourhood instead of every triangle).
bool chart_on_sheet(const Mesh& mesh, const Shape& shape, const Vector2& chart_mm,
                    const std::vector<Index>& near_triangles);

/// The box the sheet's chart points fill: a cylinder's rectangle [0, L] × [0, Rα]; otherwise the
/// mesh's nodes' extent in x and y.
Eigen::AlignedBox2d chart_box(const Mesh& mesh, const Shape& shape);

}  // namespace emit
