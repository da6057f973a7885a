#pragma once
/// \file contact_outline.hpp
/// A contact's outline as a polygon in the sheet's chart [mm] (sensor/surface.hpp: x, y on a flat
/// sheet, a cap and a file's surface seen from +z; along the axis and around it on a cylinder),
/// counter-clockwise, closed implicitly (the last vertex joins the first), at most
/// Outline::capacity vertices, held in place so that a contact copies without allocating.
///
///   - contact fitting's disc: the polygon inscribed in its circle (ellipse_outline);
///   - the `shapes` method's ellipse: the polygon inscribed in it;
///   - a linear method's region (`paper`, `noser`, `laplacian`): the image's level line at the
///     threshold that selected the region (paper §2.4), by marching triangles on the
///     reconstruction mesh (RegionOutliner): the element values averaged to the nodes (area
///     weighted), the line where that piecewise-linear field crosses the threshold, around the
///     region's elements; the sheet's border closes it where the region reaches the border.
///     Simplified to the capacity by dropping, one at a time, the vertex whose triangle with its
///     neighbours is smallest (Visvalingam–Whyatt), so the area changes by at most the sum of
///     those triangles.
///
/// Offline/online split: RegionOutliner's constructor precomputes the mesh's edges, node-to-
/// triangle adjacency and each triangle's chart points; outline() runs per frame and allocates
/// nothing.
#include <array>
#include <cstdint>
#include <span>
#include <vector>

#include "emit/core/types.hpp"
#include "emit/mesh/mesh.hpp"
#include "emit/sensor/sensor.hpp"

namespace emit {

struct Outline {
  /// The most vertices an outline has: enough that a circle's inscribed polygon has 99.8 % of its
  /// area (n/(2π)·sin(2π/n)), few enough that a frame's contacts stay small (float vertices:
  /// 0.1 µm at a metre).
  static constexpr int capacity = 64;
  std::array<std::array<float, 2>, capacity> vertices_mm{};  ///< (x, y); plain floats, zeroed
  int size = 0;                                              ///< 0: no outline

  bool empty() const { return size == 0; }
  Vector2 vertex_mm(int i) const {
    const std::array<float, 2>& v = vertices_mm[static_cast<std::size_t>(i)];
    return {v[0], v[1]};
  }
  /// Appends a vertex; ignored beyond the capacity.
  void push_back(const Vector2& p_mm) {
    if (size < capacity)
      vertices_mm[static_cast<std::size_t>(size++)] = {static_cast<float>(p_mm.x()), static_cast<float>(p_mm.y())};
  }
  void clear() { size = 0; }
  /// The enclosed area by the shoelace formula [mm²]: positive for counter-clockwise vertices.
  double area_mm2() const;
};

/// How many vertices ellipse_outline puts on a disc's or an ellipse's outline.
inline constexpr int ellipse_outline_vertices = 48;

/// The polygon of `vertex_count` (≤ Outline::capacity) vertices inscribed in the ellipse of these
/// semi-axes about `centre_mm`, its major axis at `orientation_deg` from the chart's first axis,
/// counter-clockwise, the first vertex at the major axis' end. Its area is
/// π a b · n/(2π) · sin(2π/n). A circle: semi_major = semi_minor. Non-finite or non-positive
/// semi-axes give no outline.
void ellipse_outline(const Vector2& centre_mm, double semi_major_mm, double semi_minor_mm, double orientation_deg,
                     Outline& out, int vertex_count = ellipse_outline_vertices);

/// The level line of an image around a region of elements, by marching triangles (file comment).
class RegionOutliner {
 public:
  explicit RegionOutliner(const Mesh& mesh, Shape surface = {});

  /// The outline of `region` (element indices, edge-connected): where the image (#F element
  /// values, e.g. δφ) averaged to the nodes crosses `level`, the region's elements counting
  /// image − level, the other elements −|image − level| (so a neighbouring region's elements do
  /// not join it). Of the closed lines around the region the one enclosing the largest area.
  /// `level` NaN: the region's indicator's (+1 in it, −1 outside) zero line instead, a smoothed
  /// boundary of its elements. No line (a region of a few elements whose nodes all average below
  /// the level): `out` is left empty.
  void outline(const Vector& image, double level, std::span<const int> region, Outline& out);

  /// Σ over the region's elements of their area [mm²], and of those touching a node on the
  /// region's boundary (a node with an element of the region and one not in it): the outline's
  /// area lies within the second of the first, before simplification (tests).
  double band_area_mm2(std::span<const int> region);

 private:
  struct Segment {
    int from, to;  ///< point ids: an edge's index (its crossing) or edge_count + a node's index
    Vector2 start_mm;
  };
  Shape surface_;
  int edge_count_ = 0;
  double sleeve_period_mm_ = 0;  ///< 2πR around a sleeve, else 0 (the chart's v wraps)
  std::vector<double> areas_mm2_;
  /// Per triangle, its nodes ordered counter-clockwise in the chart, their chart points (around
  /// a sleeve unwrapped next to the first), and the index of its edges k → k+1 and whether each
  /// is on the mesh's border.
  std::vector<std::array<int, 3>> corners_;
  std::vector<std::array<Vector2, 3>> corner_charts_mm_;
  std::vector<std::array<int, 3>> edges_;
  std::vector<std::array<std::uint8_t, 3>> on_border_;
  std::vector<int> node_offsets_, node_triangles_;  ///< CSR: the triangles at each node
  std::vector<std::uint8_t> node_on_border_;
  // Per-frame scratch, sized at construction.
  std::vector<std::uint8_t> in_region_;
  std::vector<int> node_value_stamp_, node_seen_stamp_, triangle_stamp_;  ///< == stamp_: done this call
  int stamp_ = 0;
  std::vector<double> node_value_;
  std::vector<int> band_;
  std::vector<Segment> segments_;
  std::vector<int> starting_at_;  ///< per point id, the segment starting there (−1: none)
  std::vector<std::uint8_t> used_;
  std::vector<Vector2> loop_, best_;
  std::vector<double> weights_;
  std::vector<int> previous_, next_;

  double node_value(int node, const Vector& image, double level);
  void mark_band(std::span<const int> region);
  int next_stamp();
};

}  // namespace emit
