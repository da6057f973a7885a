#include "emit/mesh/flatness.hpp"

namespace emit {

bool is_flat(const Mesh& mesh) {
  if (mesh.node_count() == 0) return true;
  const auto xy = mesh.nodes_mm.leftCols<2>();
  const double extent_mm = (xy.colwise().maxCoeff() - xy.colwise().minCoeff()).maxCoeff();
  return mesh.nodes_mm.col(2).cwiseAbs().maxCoeff() <= 1e-9 * extent_mm;
}

}  // namespace emit
