#include "emit/fem/electrode_dofs.hpp"

#include "emit/core/errors.hpp"

namespace emit {

ElectrodeDofs number_electrode_dofs(const Mesh& mesh) {
  ElectrodeDofs dofs;
  dofs.electrode_count = mesh.electrode_count();
  dofs.dof_of_node.assign(static_cast<std::size_t>(mesh.node_count()), -1);
  for (int e = 0; e < mesh.electrode_count(); ++e) {
    if (mesh.electrode_nodes[e].empty()) throw InvalidInput("electrode " + std::to_string(e) + " has no mesh node");
    for (int v : mesh.electrode_nodes[e]) {
      if (dofs.dof_of_node[v] >= 0)
        throw InvalidInput("mesh node " + std::to_string(v) + " lies on electrodes " +
                           std::to_string(dofs.dof_of_node[v]) + " and " + std::to_string(e));
      dofs.dof_of_node[v] = e;
    }
  }
  int next = dofs.electrode_count;
  for (int& d : dofs.dof_of_node)
    if (d < 0) d = next++;
  dofs.dof_count = next;
  return dofs;
}

SparseMatrix to_dof_space(const SparseMatrix& node_matrix, const ElectrodeDofs& dofs) {
  std::vector<Eigen::Triplet<double, int>> entries;
  entries.reserve(static_cast<std::size_t>(node_matrix.nonZeros()));
  for (int col = 0; col < node_matrix.outerSize(); ++col)
    for (SparseMatrix::InnerIterator it(node_matrix, col); it; ++it)
      entries.emplace_back(dofs.dof_of_node[it.row()], dofs.dof_of_node[col], it.value());
  SparseMatrix A(dofs.dof_count, dofs.dof_count);
  A.setFromTriplets(entries.begin(), entries.end());
  return A;
}

SparseMatrix contact_to_dof_space(const Mesh& mesh, const ContactLoad& contact, const ElectrodeDofs& dofs) {
  std::vector<Eigen::Triplet<double, int>> entries;
  entries.reserve(9 * contact.triangles.size());
  for (std::size_t i = 0; i < contact.triangles.size(); ++i) {
    const auto v = mesh.triangles.row(contact.triangles[i]);
    for (int a = 0; a < 3; ++a)
      for (int b = 0; b < 3; ++b)
        entries.emplace_back(dofs.dof_of_node[v[a]], dofs.dof_of_node[v[b]], contact.local_S[i](a, b));
  }
  SparseMatrix C(dofs.dof_count, dofs.dof_count);
  C.setFromTriplets(entries.begin(), entries.end());
  return C;
}

}  // namespace emit
