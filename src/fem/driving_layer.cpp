#include "emit/fem/driving_layer.hpp"

#include <algorithm>

#include "emit/core/errors.hpp"
#include "emit/fem/stiffness.hpp"

namespace emit {

DrivingLayer bottom_fed_driving_layer(const Mesh& mesh, double sheet_resistance_ohm_per_sq, double fraction) {
  if (!(sheet_resistance_ohm_per_sq > 0)) throw InvalidInput("driving layer sheet resistance must be positive");
  const double y_min = mesh.nodes_mm.col(1).minCoeff(), y_max = mesh.nodes_mm.col(1).maxCoeff();
  const double y_bus = y_min + fraction * (y_max - y_min);
  DrivingLayer layer{Vector::Constant(mesh.triangle_count(), 1.0 / sheet_resistance_ohm_per_sq), {}};
  for (const auto& edge : mesh.border_edges())
    for (int node : edge)
      if (mesh.nodes_mm(node, 1) <= y_bus) layer.feed_nodes.push_back(node);
  std::sort(layer.feed_nodes.begin(), layer.feed_nodes.end());
  layer.feed_nodes.erase(std::unique(layer.feed_nodes.begin(), layer.feed_nodes.end()), layer.feed_nodes.end());
  return layer;
}

namespace {

using Triplets = std::vector<Eigen::Triplet<double, int>>;

/// Adds c at (row, column) of the coupled system, where a fed driving node's column is a known
/// potential (1 per volt of drive) and so moves to the right-hand side; a fed row is no equation.
struct CoupledEntries {
  Triplets& entries;
  Vector& drive;
  void add(int row, int column, bool column_fed, double c) const {
    if (row < 0) return;
    if (column_fed) drive[row] -= c;
    else entries.emplace_back(row, column, c);
  }
};

}  // namespace

CoupledAssembler::CoupledAssembler(const Mesh& mesh, const ElectrodeDofs& dofs,
                                   const SparseMatrix& probing_stiffness_dof, const DrivingLayer& layer)
    : mesh_(&mesh), dofs_(&dofs), free_index_(mesh.node_count(), 0) {
  if (layer.feed_nodes.empty()) throw InvalidInput("the driving layer is fed nowhere");
  for (int node : layer.feed_nodes) free_index_.at(node) = -1;
  int unknowns = dofs.dof_count;
  for (int& index : free_index_)
    if (index == 0) index = unknowns++;

  const SparseMatrix K_d = assemble_stiffness(mesh, layer.element_conductance_S);
  Triplets entries;
  drive_without_contact_ = Vector::Zero(unknowns);
  const CoupledEntries add{entries, drive_without_contact_};
  for (int col = 0; col < probing_stiffness_dof.outerSize(); ++col)
    for (SparseMatrix::InnerIterator it(probing_stiffness_dof, col); it; ++it)
      entries.emplace_back(static_cast<int>(it.row()), col, it.value());
  for (int col = 0; col < K_d.outerSize(); ++col)
    for (SparseMatrix::InnerIterator it(K_d, col); it; ++it)
      add.add(free_index_[it.row()], free_index_[col], free_index_[col] < 0, it.value());
  F_without_contact_.resize(unknowns, unknowns);
  F_without_contact_.setFromTriplets(entries.begin(), entries.end());
}

CoupledSystem CoupledAssembler::system(const ContactLoad& contact) const {
  CoupledSystem s{SparseMatrix(F_without_contact_.rows(), F_without_contact_.cols()), drive_without_contact_};
  Triplets entries;
  entries.reserve(36 * contact.triangles.size());
  const CoupledEntries add{entries, s.drive};
  for (std::size_t i = 0; i < contact.triangles.size(); ++i) {
    const auto v = mesh_->triangles.row(contact.triangles[i]);
    for (int a = 0; a < 3; ++a)
      for (int b = 0; b < 3; ++b) {
        const double c = contact.local_S[i](a, b);
        const int u_a = dofs_->dof_of_node[v[a]], u_b = dofs_->dof_of_node[v[b]];
        const int d_a = free_index_[v[a]], d_b = free_index_[v[b]];
        add.add(u_a, u_b, false, c);     // g u on the probing sheet
        add.add(u_a, d_b, d_b < 0, -c);  // − g v on the probing sheet
        add.add(d_a, u_b, false, -c);    // − g u on the driving layer
        add.add(d_a, d_b, d_b < 0, c);   // g v on the driving layer
      }
  }
  s.F.setFromTriplets(entries.begin(), entries.end());
  s.F += F_without_contact_;
  return s;
}

}  // namespace emit
