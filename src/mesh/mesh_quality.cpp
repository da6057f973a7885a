#include "emit/mesh/mesh_quality.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

namespace emit {

MeshQuality measure_mesh_quality(const Mesh& mesh) {
  MeshQuality q;
  q.node_count = mesh.node_count();
  q.triangle_count = mesh.triangle_count();
  q.min_angle_deg = 180;
  q.min_area_mm2 = std::numeric_limits<double>::infinity();
  double edge_sum = 0;
  for (Index t = 0; t < mesh.triangle_count(); ++t) {
    for (int k = 0; k < 3; ++k) {
      const Vector3 p = mesh.nodes_mm.row(mesh.triangles(t, k));
      const Vector3 u = Vector3(mesh.nodes_mm.row(mesh.triangles(t, (k + 1) % 3))) - p;
      const Vector3 v = Vector3(mesh.nodes_mm.row(mesh.triangles(t, (k + 2) % 3))) - p;
      const double angle = std::atan2(u.cross(v).norm(), u.dot(v)) * 180.0 / std::numbers::pi;
      q.min_angle_deg = std::min(q.min_angle_deg, angle);
      edge_sum += u.norm();
    }
    const double area = mesh.triangle_area_mm2(t);
    q.min_area_mm2 = std::min(q.min_area_mm2, area);
    q.total_area_mm2 += area;
  }
  if (mesh.triangle_count() > 0) q.mean_edge_mm = edge_sum / (3.0 * static_cast<double>(mesh.triangle_count()));
  return q;
}

}  // namespace emit
