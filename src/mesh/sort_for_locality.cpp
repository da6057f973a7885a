#include "emit/mesh/sort_for_locality.hpp"

#include <algorithm>
#include <cstdint>
#include <numeric>

namespace emit {

namespace {

/// The bits of a 16-bit value spread to the even bits of 32 ("part 1 by 1").
std::uint32_t spread_bits(std::uint32_t v) {
  v &= 0xffffu;
  v = (v | (v << 8)) & 0x00ff00ffu;
  v = (v | (v << 4)) & 0x0f0f0f0fu;
  v = (v | (v << 2)) & 0x33333333u;
  v = (v | (v << 1)) & 0x55555555u;
  return v;
}

/// Maps a point of the mesh's bounding box to its Z-order index on a 2¹⁶ × 2¹⁶ grid.
class ZOrder {
 public:
  explicit ZOrder(const Mesh& mesh) {
    const auto xy = mesh.nodes_mm.leftCols<2>();
    low_ = xy.colwise().minCoeff().transpose();
    const Vector2 extent = xy.colwise().maxCoeff().transpose() - low_;
    scale_ = 65535.0 / std::max(extent.maxCoeff(), 1e-300);
  }
  std::uint32_t operator()(const Vector2& point_mm) const {
    const Vector2 cell = ((point_mm - low_) * scale_).cwiseMax(0.0).cwiseMin(65535.0);
    return spread_bits(static_cast<std::uint32_t>(cell.x())) | (spread_bits(static_cast<std::uint32_t>(cell.y())) << 1);
  }

 private:
  Vector2 low_;
  double scale_ = 1;
};

/// The order of 0..keys.size()-1 by key, ties in index order.
std::vector<int> order_by(const std::vector<std::uint32_t>& keys) {
  std::vector<int> order(keys.size());
  std::iota(order.begin(), order.end(), 0);
  std::stable_sort(order.begin(), order.end(), [&](int a, int b) { return keys[a] < keys[b]; });
  return order;
}

}  // namespace

Mesh sort_for_locality(const Mesh& mesh) {
  if (mesh.node_count() == 0) return mesh;
  const ZOrder z_order(mesh);

  std::vector<std::uint32_t> node_keys(static_cast<std::size_t>(mesh.node_count()));
  for (Index v = 0; v < mesh.node_count(); ++v) node_keys[v] = z_order(mesh.nodes_mm.row(v).head<2>().transpose());
  const std::vector<int> node_order = order_by(node_keys);  // new index → old
  std::vector<int> new_node(node_order.size());             // old index → new
  Mesh sorted;
  sorted.nodes_mm.resize(mesh.node_count(), 3);
  for (std::size_t v = 0; v < node_order.size(); ++v) {
    new_node[node_order[v]] = static_cast<int>(v);
    sorted.nodes_mm.row(static_cast<Index>(v)) = mesh.nodes_mm.row(node_order[v]);
  }

  std::vector<std::uint32_t> triangle_keys(static_cast<std::size_t>(mesh.triangle_count()));
  for (Index t = 0; t < mesh.triangle_count(); ++t) triangle_keys[t] = z_order(mesh.triangle_centroid_mm(t).head<2>());
  const std::vector<int> triangle_order = order_by(triangle_keys);
  sorted.triangles.resize(mesh.triangle_count(), 3);
  for (std::size_t t = 0; t < triangle_order.size(); ++t)
    for (int k = 0; k < 3; ++k)
      sorted.triangles(static_cast<Index>(t), k) = new_node[mesh.triangles(triangle_order[t], k)];

  sorted.electrode_nodes = mesh.electrode_nodes;
  for (std::vector<int>& nodes : sorted.electrode_nodes) {
    for (int& v : nodes) v = new_node[v];
    std::sort(nodes.begin(), nodes.end());
  }
  return sorted;
}

}  // namespace emit
