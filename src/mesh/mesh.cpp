#include "emit/mesh/mesh.hpp"

#include <algorithm>
#include <map>

namespace emit {

double Mesh::triangle_area_mm2(Index t) const {
  const Vector3 a = nodes_mm.row(triangles(t, 0)), b = nodes_mm.row(triangles(t, 1)), c = nodes_mm.row(triangles(t, 2));
  return 0.5 * (b - a).cross(c - a).norm();
}

Vector3 Mesh::triangle_centroid_mm(Index t) const {
  return (nodes_mm.row(triangles(t, 0)) + nodes_mm.row(triangles(t, 1)) + nodes_mm.row(triangles(t, 2))).transpose() /
         3.0;
}

bool Mesh::triangle_contains_xy(Index t, const Vector2& p) const {
  double sign[3];
  for (int k = 0; k < 3; ++k) {
    const Vector2 a = nodes_mm.row(triangles(t, k)).head<2>(), b = nodes_mm.row(triangles(t, (k + 1) % 3)).head<2>();
    sign[k] = (b.x() - a.x()) * (p.y() - a.y()) - (b.y() - a.y()) * (p.x() - a.x());
  }
  return (sign[0] >= 0 && sign[1] >= 0 && sign[2] >= 0) || (sign[0] <= 0 && sign[1] <= 0 && sign[2] <= 0);
}

bool Mesh::contains_xy(const Vector2& p) const {
  for (Index t = 0; t < triangle_count(); ++t)
    if (triangle_contains_xy(t, p)) return true;
  return false;
}

bool Mesh::contains_xy(const Vector2& p, const std::vector<Index>& among) const {
  return std::any_of(among.begin(), among.end(), [&](Index t) { return triangle_contains_xy(t, p); });
}

std::vector<std::array<int, 2>> Mesh::border_edges() const {
  std::map<std::array<int, 2>, int> uses;
  for (Index t = 0; t < triangle_count(); ++t)
    for (int k = 0; k < 3; ++k) {
      int a = triangles(t, k), b = triangles(t, (k + 1) % 3);
      ++uses[{std::min(a, b), std::max(a, b)}];
    }
  std::vector<std::array<int, 2>> edges;
  for (const auto& [edge, count] : uses)
    if (count == 1) edges.push_back(edge);
  return edges;
}

std::vector<std::array<int, 2>> Mesh::electrode_edges(int e) const {
  const auto& nodes = electrode_nodes.at(e);
  const auto on = [&](int v) { return std::binary_search(nodes.begin(), nodes.end(), v); };
  // Only the edges with both ends on the electrode are counted (all of them, per electrode, made
  // writing a mesh of 400 electrodes take minutes).
  std::map<std::array<int, 2>, int> uses;
  for (Index t = 0; t < triangle_count(); ++t)
    for (int k = 0; k < 3; ++k) {
      const int a = triangles(t, k), b = triangles(t, (k + 1) % 3);
      if (on(a) && on(b)) ++uses[{std::min(a, b), std::max(a, b)}];
    }
  std::vector<std::array<int, 2>> edges;
  for (const auto& [edge, count] : uses)
    if (count == 1) edges.push_back(edge);
  return edges;
}

}  // namespace emit
