#include "emit/model/jacobian.hpp"

#include <algorithm>
#include <array>

#include <Eigen/Dense>
#include <Eigen/SparseCholesky>
#include <cmath>

#include "emit/core/large_matrix.hpp"
#include "emit/fem/electrode_dofs.hpp"
#include "emit/fem/stiffness.hpp"
#include "emit/fem/supernodal_cholesky.hpp"

namespace emit {

namespace {

using SmallMatrix = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, 0, 3, 3>;
using SmallVector = Eigen::Matrix<double, Eigen::Dynamic, 1, 0, 3, 1>;

/// The distinct dofs of a triangle's nodes (an electrode's nodes share one).
struct ElementDofs {
  std::array<int, 3> dof{};
  int size = 0;
  ElementDofs(const Mesh& mesh, const ElectrodeDofs& dofs, Index t) {
    for (int c = 0; c < 3; ++c) {
      const int d = dofs.dof_of_node[mesh.triangles(t, c)];
      if (std::find(dof.begin(), dof.begin() + size, d) == dof.begin() + size) dof[size++] = d;
    }
  }
};

/// Green's function of the sheet with electrode 0 grounded: G0 = A0⁻¹ on dofs (dof 0 is the
/// ground, so G0 vanishes on its row and column).
struct GroundedGreen {
  Matrix electrode_rows;  ///< N × n: G0(e_m, d) = w_m(d), a dof's N values contiguous; row 0 is zero
  SparseMatrix selected;  ///< A0⁻¹ on A0's pattern (lower), reduced indices (dof − 1)

  /// G0 between two dofs coupled by an element.
  double between(int a, int b) const {
    if (a == 0 || b == 0) return 0.0;
    return selected.coeff(std::max(a, b) - 1, std::min(a, b) - 1);
  }
  double at_electrode(int d, int m) const { return electrode_rows(m, d); }
};

/// One supernodal factorisation gives both the N − 1 solves and, by selected inversion, G0 on
/// every element's nodes (supernodal_cholesky.hpp says why not the simplicial factor).
GroundedGreen grounded_green(const SparseMatrix& stiffness_dof, int electrode_count) {
  const Index n = stiffness_dof.rows();
  SupernodalCholesky cholesky;
  cholesky.factorize(stiffness_dof.bottomRightCorner(n - 1, n - 1));
  Matrix unit_currents = Matrix::Zero(n - 1, electrode_count - 1);
  for (int m = 1; m < electrode_count; ++m) unit_currents(m - 1, m - 1) = 1.0;
  GroundedGreen green;
  green.electrode_rows = Matrix::Zero(electrode_count, n);
  green.electrode_rows.bottomRightCorner(electrode_count - 1, n - 1) = cholesky.solve(unit_currents).transpose();
  green.selected = cholesky.selected_inverse();
  return green;
}

/// Currents q into held nodes at 1 V: G q = 1, by pivoted LDLᵀ. Three held nodes (any element
/// off the grounded electrode) take Eigen's fixed-size path, which it unrolls: the solves were
/// half the Jacobian's element loop.
SmallVector held_currents(const SmallMatrix& G) {
  if (G.rows() == 3) return Eigen::Matrix3d(G).ldlt().solve(Eigen::Vector3d::Ones());
  return G.ldlt().solve(SmallVector::Ones(G.rows()));
}

/// Rows of each grounding: rows_of_ground[l] lists the measurement rows with ground l.
std::vector<std::vector<int>> rows_by_ground(const MeasurementSet& measurements) {
  std::vector<std::vector<int>> rows(static_cast<std::size_t>(measurements.electrode_count));
  for (int r = 0; r < measurements.size(); ++r) rows[measurements.ground[r]].push_back(r);
  return rows;
}

/// Column t of J: for each ground l, the element's nodes off electrode l held at 1 V.
void jacobian_column(const GroundedGreen& G0, const ElementDofs& element, const MeasurementSet& measurements,
                     const std::vector<std::vector<int>>& rows, double* column) {
  // G0 among the element's dofs, looked up once for all N groundings.
  std::array<std::array<double, 3>, 3> G0_element{};
  for (int i = 0; i < element.size; ++i)
    for (int j = 0; j <= i; ++j) G0_element[i][j] = G0_element[j][i] = G0.between(element.dof[i], element.dof[j]);
  for (int l = 0; l < static_cast<int>(rows.size()); ++l) {
    if (rows[l].empty()) continue;   // an excluded electrode
    std::array<int, 3> S{}, held{};  // held dofs, and their place in `element`
    int size = 0;
    for (int i = 0; i < element.size; ++i)
      if (element.dof[i] != l) S[size] = element.dof[i], held[size++] = i;
    if (size == 0) {  // the whole element lies on the grounded electrode
      for (int r : rows[l]) column[r] = 0.0;
      continue;
    }
    // w_l(x) = G0(x, e_l); G_l(x, y) = G0(x, y) − w_l(x) − w_l(y) + w_l(e_l).
    const double w_ll = G0.at_electrode(l, l);
    SmallMatrix G_SS(size, size);
    for (int i = 0; i < size; ++i)
      for (int j = 0; j < size; ++j)
        G_SS(i, j) = G0_element[held[i]][held[j]] - G0.at_electrode(S[i], l) - G0.at_electrode(S[j], l) + w_ll;
    // Currents q into the held nodes: G_l(S, S) q = 1 (the nodes at 1 V).
    const SmallVector q = held_currents(G_SS);
    for (int r : rows[l]) {
      const int m = measurements.sense[r];
      double V = 0;
      for (int i = 0; i < size; ++i)
        V += q[i] * (G0.at_electrode(S[i], m) - G0.at_electrode(S[i], l) - G0.at_electrode(m, l) + w_ll);
      column[r] = V;
    }
  }
}

}  // namespace

Matrix compute_jacobian(const Mesh& mesh, const MeasurementSet& measurements) {
  const ElectrodeDofs dofs = number_electrode_dofs(mesh);
  const GroundedGreen G0 = grounded_green(to_dof_space(assemble_stiffness(mesh, 1.0), dofs), dofs.electrode_count);
  const auto rows = rows_by_ground(measurements);
  // Every entry is written below (each row has one ground), so J is not zeroed first.
  Matrix J = large_matrix(measurements.size(), mesh.triangle_count());
  for (Index t = 0; t < mesh.triangle_count(); ++t)
    jacobian_column(G0, ElementDofs(mesh, dofs, t), measurements, rows, J.col(t).data());
  return J;
}

Matrix compute_jacobian_brute_force(const Mesh& mesh, const MeasurementSet& measurements) {
  const ElectrodeDofs dofs = number_electrode_dofs(mesh);
  const SparseMatrix K = to_dof_space(assemble_stiffness(mesh, 1.0), dofs);
  const int n = dofs.dof_count;
  Matrix J = Matrix::Zero(measurements.size(), mesh.triangle_count());
  for (Index t = 0; t < mesh.triangle_count(); ++t) {
    const ElementDofs element(mesh, dofs, t);
    for (int l = 0; l < dofs.electrode_count; ++l) {
      // Fixed: dof l at 0 V, the element's other dofs at 1 V; a direct solve for all the rest.
      std::vector<double> held(static_cast<std::size_t>(n), std::nan(""));
      held[l] = 0;
      for (int i = 0; i < element.size; ++i)
        if (element.dof[i] != l) held[element.dof[i]] = 1;
      std::vector<int> free_index(static_cast<std::size_t>(n), -1);
      int free_count = 0;
      for (int d = 0; d < n; ++d)
        if (std::isnan(held[d])) free_index[d] = free_count++;
      std::vector<Eigen::Triplet<double, int>> entries;
      Vector rhs = Vector::Zero(free_count);
      for (int c = 0; c < n; ++c)
        for (SparseMatrix::InnerIterator it(K, c); it; ++it) {
          const int r = free_index[it.row()];
          if (r < 0) continue;
          if (free_index[c] >= 0) entries.emplace_back(r, free_index[c], it.value());
          else rhs[r] -= it.value() * held[c];
        }
      SparseMatrix A(free_count, free_count);
      A.setFromTriplets(entries.begin(), entries.end());
      const Vector u_free = Eigen::SimplicialLDLT<SparseMatrix>(A).solve(rhs);
      for (int r = 0; r < measurements.size(); ++r) {
        if (measurements.ground[r] != l) continue;
        const int m = measurements.sense[r];
        J(r, t) = free_index[m] >= 0 ? u_free[free_index[m]] : held[m];
      }
    }
  }
  return J;
}

}  // namespace emit
