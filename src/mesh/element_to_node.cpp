#include "emit/mesh/element_to_node.hpp"

namespace emit {

Vector element_to_node(const Mesh& mesh, const Vector& element_values) {
  Vector sum = Vector::Zero(mesh.node_count()), weight = Vector::Zero(mesh.node_count());
  for (Index t = 0; t < mesh.triangle_count(); ++t) {
    const double area = mesh.triangle_area_mm2(t);
    for (int c = 0; c < 3; ++c) {
      sum[mesh.triangles(t, c)] += area * element_values[t];
      weight[mesh.triangles(t, c)] += area;
    }
  }
  return sum.cwiseQuotient(weight.cwiseMax(1e-300));
}

}  // namespace emit
