#include "emit/fem/complete_electrode_model.hpp"

#include <cmath>

#include "emit/core/errors.hpp"
#include "emit/fem/sparse_cholesky.hpp"
#include "emit/fem/stiffness.hpp"

namespace emit {

struct CompleteElectrodeModel::Impl {
  int electrodes = 0;
  Index nodes = 0;
  /// Unknown of each node: its electrode's U_l when merged (shunt), else its own. Unknown l < N
  /// is U_l; unknown 0 (U_0 = 0) is then dropped, so row r of the system is unknown r + 1.
  std::vector<int> unknown_of_node;
  int unknowns = 0;
  SparseCholesky cholesky;

  /// Solve for all unknowns (U_0 = 0 included), one column per drive.
  Matrix solve(const Matrix& currents_A) const {
    if (currents_A.rows() != electrodes)
      throw InvalidInput("EIT drive: " + std::to_string(currents_A.rows()) + " currents for " +
                         std::to_string(electrodes) + " electrodes");
    for (Index p = 0; p < currents_A.cols(); ++p)
      if (std::abs(currents_A.col(p).sum()) > 1e-9 * currents_A.col(p).cwiseAbs().sum() ||
          !currents_A.col(p).allFinite())
        throw InvalidInput("EIT drive " + std::to_string(p) + ": its currents must be finite and sum to 0");
    Matrix rhs = Matrix::Zero(unknowns - 1, currents_A.cols());
    rhs.topRows(electrodes - 1) = currents_A.bottomRows(electrodes - 1);
    Matrix x = Matrix::Zero(unknowns, currents_A.cols());
    x.bottomRows(unknowns - 1) = cholesky.solve(rhs);
    // The reference: Σ_l U_l = 0.
    const Eigen::RowVectorXd mean = x.topRows(electrodes).colwise().mean();
    x.rowwise() -= mean;
    return x;
  }
};

CompleteElectrodeModel::CompleteElectrodeModel(const Mesh& mesh, const Vector& element_conductance_S,
                                               const std::vector<double>& contact_impedance_ohm_mm)
    : impl_(std::make_unique<Impl>()) {
  Impl& m = *impl_;
  m.electrodes = mesh.electrode_count();
  m.nodes = mesh.node_count();
  if (m.electrodes < 2) throw InvalidInput("EIT: a sheet needs at least 2 electrodes");
  if (static_cast<int>(contact_impedance_ohm_mm.size()) != m.electrodes)
    throw InvalidInput("EIT: " + std::to_string(contact_impedance_ohm_mm.size()) + " contact impedances for " +
                       std::to_string(m.electrodes) + " electrodes");
  for (int l = 0; l < m.electrodes; ++l)
    if (!(contact_impedance_ohm_mm[l] >= 0) || !std::isfinite(contact_impedance_ohm_mm[l]))
      throw InvalidInput("EIT: electrode " + std::to_string(l) + "'s contact impedance must be finite and >= 0");
  // Number the unknowns: U_0 … U_{N−1}, then every node not merged into a shunt electrode.
  m.unknown_of_node.assign(static_cast<std::size_t>(m.nodes), -1);
  for (int l = 0; l < m.electrodes; ++l)
    for (int v : mesh.electrode_nodes[l]) {
      if (m.unknown_of_node[v] == -2 || (m.unknown_of_node[v] >= 0 && m.unknown_of_node[v] != l))
        throw InvalidInput("EIT: mesh node " + std::to_string(v) + " lies on two electrodes");
      m.unknown_of_node[v] = contact_impedance_ohm_mm[l] == 0 ? l : -2;
    }
  m.unknowns = m.electrodes;
  for (int& u : m.unknown_of_node)
    if (u < 0) u = m.unknowns++;

  std::vector<Eigen::Triplet<double, int>> entries;
  const SparseMatrix K = assemble_stiffness(mesh, element_conductance_S);
  for (int col = 0; col < K.outerSize(); ++col)
    for (SparseMatrix::InnerIterator it(K, col); it; ++it)
      entries.emplace_back(m.unknown_of_node[it.row()], m.unknown_of_node[col], it.value());
  for (int l = 0; l < m.electrodes; ++l) {
    const double z = contact_impedance_ohm_mm[l];
    const auto edges = mesh.electrode_edges(l);
    if (edges.empty()) throw InvalidInput("EIT: electrode " + std::to_string(l) + " has no border edge");
    if (z == 0) continue;
    for (const auto& edge : edges) {
      const double h = (mesh.nodes_mm.row(edge[0]) - mesh.nodes_mm.row(edge[1])).norm();
      const int a = m.unknown_of_node[edge[0]], b = m.unknown_of_node[edge[1]];
      // ∫ φ_i φ_j ds on the edge: h/3 on the diagonal, h/6 off it; ∫ φ_i ds = h/2.
      entries.emplace_back(a, a, h / (3 * z));
      entries.emplace_back(b, b, h / (3 * z));
      entries.emplace_back(a, b, h / (6 * z));
      entries.emplace_back(b, a, h / (6 * z));
      for (int node : {a, b}) {
        entries.emplace_back(node, l, -h / (2 * z));
        entries.emplace_back(l, node, -h / (2 * z));
      }
      entries.emplace_back(l, l, h / z);
    }
  }
  // U_0 = 0: drop unknown 0.
  std::vector<Eigen::Triplet<double, int>> grounded;
  grounded.reserve(entries.size());
  for (const auto& t : entries)
    if (t.row() > 0 && t.col() > 0) grounded.emplace_back(t.row() - 1, t.col() - 1, t.value());
  SparseMatrix A(m.unknowns - 1, m.unknowns - 1);
  A.setFromTriplets(grounded.begin(), grounded.end());
  m.cholesky.analyze(A);
  m.cholesky.factorize(A);
}

CompleteElectrodeModel::~CompleteElectrodeModel() = default;
CompleteElectrodeModel::CompleteElectrodeModel(CompleteElectrodeModel&&) noexcept = default;
CompleteElectrodeModel& CompleteElectrodeModel::operator=(CompleteElectrodeModel&&) noexcept = default;

int CompleteElectrodeModel::electrode_count() const { return impl_->electrodes; }

Matrix CompleteElectrodeModel::electrode_potentials_V(const Matrix& currents_A) const {
  return impl_->solve(currents_A).topRows(impl_->electrodes);
}

Matrix CompleteElectrodeModel::node_potentials_V(const Matrix& currents_A) const {
  const Matrix x = impl_->solve(currents_A);
  Matrix u(impl_->nodes, currents_A.cols());
  for (Index v = 0; v < impl_->nodes; ++v) u.row(v) = x.row(impl_->unknown_of_node[static_cast<std::size_t>(v)]);
  return u;
}

}  // namespace emit
