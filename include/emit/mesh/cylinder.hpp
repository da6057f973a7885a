#pragma once
/// \file cylinder.hpp
/// A cylinder's mesh from its chart's (sensor/surface.hpp): the rectangle L × Rα meshed flat, each
/// node moved onto the cylinder by surface_point_mm. The map keeps lengths along the surface, so
/// the rectangle is meshed at the element size itself, and a triangle's edges shrink only as a
/// chord falls short of its arc: by at most 1 − sinc(h / 2R) ≈ h² / (24 R²) for an edge h long.
/// A triangle counter-clockwise in the chart (seen from +z) faces out of the cylinder after the
/// wrap, as ∂P/∂u × ∂P/∂v = (0, sin θ, cos θ) is the outward normal.
///
/// A sleeve (α = 360°) is periodic in v: its chart's edges v = 0 and v = 2πR are one seam, meshed
/// with the same nodes (a periodic constraint in Gmsh), and after the wrap each node of the edge
/// v = 2πR is merged into its twin on v = 0, so the border is the two rims alone.
#include "emit/mesh/mesh.hpp"
#include "emit/sensor/sensor.hpp"

namespace emit {

/// Moves every node of a mesh of the chart (its (x, y) the chart point (u, v), z ignored) onto the
/// cylinder `shape`. On a sleeve, then merges the seam's nodes: every node at v = 2πR (within
/// 1e-9 of the chart's size) is replaced by the node at v = 0 with the same u; the other nodes
/// keep their relative order (so a mesh numbered for locality in the chart stays so), triangles
/// their orientation, electrodes their nodes.
/// \pre shape.kind is ShapeKind::cylinder.
/// \throw InvalidInput if a sleeve's two seam edges do not carry the same node distribution.
void wrap_onto_cylinder(Mesh& mesh, const Shape& shape);

}  // namespace emit
