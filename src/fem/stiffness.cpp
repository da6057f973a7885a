#include "emit/fem/stiffness.hpp"

#include <vector>

namespace emit {

Eigen::Matrix3d local_stiffness(const Vector3& p0, const Vector3& p1, const Vector3& p2, double conductance_S) {
  const Vector3 e[3] = {p2 - p1, p0 - p2, p1 - p0};
  const double twice_area = e[2].cross(-e[1]).norm();
  Eigen::Matrix3d k;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) k(i, j) = conductance_S * e[i].dot(e[j]) / (2.0 * twice_area);
  return k;
}

SparseMatrix assemble_stiffness(const Mesh& mesh, double conductance_S) {
  return assemble_stiffness(mesh, Vector::Constant(mesh.triangle_count(), conductance_S));
}

SparseMatrix assemble_stiffness(const Mesh& mesh, const Vector& element_conductance_S) {
  std::vector<Eigen::Triplet<double, int>> entries;
  entries.reserve(static_cast<std::size_t>(9 * mesh.triangle_count()));
  for (Index t = 0; t < mesh.triangle_count(); ++t) {
    const auto v = mesh.triangles.row(t);
    const Eigen::Matrix3d k = local_stiffness(mesh.nodes_mm.row(v[0]), mesh.nodes_mm.row(v[1]), mesh.nodes_mm.row(v[2]),
                                              element_conductance_S[t]);
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) entries.emplace_back(v[i], v[j], k(i, j));
  }
  SparseMatrix K(mesh.node_count(), mesh.node_count());
  K.setFromTriplets(entries.begin(), entries.end());
  return K;
}

}  // namespace emit
