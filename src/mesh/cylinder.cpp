#include "emit/mesh/cylinder.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <vector>

#include "emit/core/errors.hpp"
#include "emit/sensor/surface.hpp"

namespace emit {

namespace {

/// Nodes of the chart mesh on the line v = v_mm, sorted by u.
std::vector<int> nodes_on_edge(const Mesh& mesh, double v_mm, double tolerance_mm) {
  std::vector<int> nodes;
  for (Index n = 0; n < mesh.node_count(); ++n)
    if (std::abs(mesh.nodes_mm(n, 1) - v_mm) <= tolerance_mm) nodes.push_back(static_cast<int>(n));
  std::sort(nodes.begin(), nodes.end(), [&](int a, int b) { return mesh.nodes_mm(a, 0) < mesh.nodes_mm(b, 0); });
  return nodes;
}

/// Replaces every node of the chart's edge v = 2πR by its twin on v = 0 and drops it.
void merge_seam(Mesh& mesh, const Shape& shape) {
  const double round_mm = 2 * std::numbers::pi * shape.radius_mm;
  const double tolerance_mm = 1e-9 * std::max(round_mm, shape.length_mm);
  const std::vector<int> bottom = nodes_on_edge(mesh, 0.0, tolerance_mm);
  const std::vector<int> top = nodes_on_edge(mesh, round_mm, tolerance_mm);
  if (top.size() != bottom.size())
    throw InvalidInput("meshing the sleeve: its seam's two edges got " + std::to_string(bottom.size()) + " and " +
                       std::to_string(top.size()) + " nodes; they must match");
  std::vector<int> target(static_cast<std::size_t>(mesh.node_count()));
  for (Index n = 0; n < mesh.node_count(); ++n) target[n] = static_cast<int>(n);
  for (std::size_t k = 0; k < top.size(); ++k) {
    if (std::abs(mesh.nodes_mm(top[k], 0) - mesh.nodes_mm(bottom[k], 0)) > tolerance_mm) {
      char text[200];
      std::snprintf(text, sizeof text,
                    "meshing the sleeve: its seam's edges have nodes at different places (u = %.9g and %.9g mm)",
                    mesh.nodes_mm(bottom[k], 0), mesh.nodes_mm(top[k], 0));
      throw InvalidInput(text);
    }
    target[top[k]] = bottom[k];
  }
  // Renumber the kept nodes in their order.
  std::vector<int> new_index(target.size(), -1);
  int kept = 0;
  for (std::size_t n = 0; n < target.size(); ++n)
    if (target[n] == static_cast<int>(n)) new_index[n] = kept++;
  const auto renumbered = [&](int n) { return new_index[target[n]]; };
  Mesh merged;
  merged.nodes_mm.resize(kept, 3);
  for (std::size_t n = 0; n < target.size(); ++n)
    if (new_index[n] >= 0) merged.nodes_mm.row(new_index[n]) = mesh.nodes_mm.row(static_cast<Index>(n));
  merged.triangles.resize(mesh.triangle_count(), 3);
  for (Index t = 0; t < mesh.triangle_count(); ++t)
    for (int k = 0; k < 3; ++k) merged.triangles(t, k) = renumbered(mesh.triangles(t, k));
  for (const auto& nodes : mesh.electrode_nodes) {
    std::vector<int> moved;
    moved.reserve(nodes.size());
    for (int n : nodes) moved.push_back(renumbered(n));
    std::sort(moved.begin(), moved.end());
    moved.erase(std::unique(moved.begin(), moved.end()), moved.end());
    merged.electrode_nodes.push_back(std::move(moved));
  }
  mesh = std::move(merged);
}

}  // namespace

void wrap_onto_cylinder(Mesh& mesh, const Shape& shape) {
  // Merge in the chart, where the twins are told apart by v; the wrap then moves the kept nodes.
  if (is_sleeve(shape)) merge_seam(mesh, shape);
  for (Index n = 0; n < mesh.node_count(); ++n)
    mesh.nodes_mm.row(n) = surface_point_mm(shape, {mesh.nodes_mm(n, 0), mesh.nodes_mm(n, 1)}).transpose();
}

}  // namespace emit
