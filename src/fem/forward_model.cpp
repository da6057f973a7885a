#include "emit/fem/forward_model.hpp"

#include <cmath>
#include <optional>
#include <string>

#include <Eigen/Dense>

#include "emit/core/errors.hpp"
#include "emit/fem/driving_layer.hpp"
#include "emit/fem/electrode_dofs.hpp"
#include "emit/fem/sparse_cholesky.hpp"
#include "emit/fem/stiffness.hpp"

namespace emit {

struct ForwardModel::Impl {
  Mesh mesh;
  ElectrodeDofs dofs;
  SparseMatrix stiffness_dof;               ///< K in dof space [S]
  std::optional<CoupledAssembler> driving;  ///< a resistive driving layer; none: an equipotential
  SparseCholesky cholesky;                  ///< the grounded pattern analysed once; each solve factorises into it
  std::vector<double> series_ohm;           ///< per electrode; empty: grounded directly

  void set_mesh(Mesh new_mesh) {
    if (new_mesh.electrode_count() < 2) throw InvalidInput("the mesh needs at least 2 electrodes");
    mesh = std::move(new_mesh);
    dofs = number_electrode_dofs(mesh);
  }

  /// Stiffness in dof space, and the symbolic analysis of its grounded pattern (done once).
  void assemble(const Vector& element_conductance_S) {
    stiffness_dof = to_dof_space(assemble_stiffness(mesh, element_conductance_S), dofs);
    const int n = dofs.dof_count;
    cholesky.analyze(stiffness_dof.bottomRightCorner(n - 1, n - 1));
  }

  /// The system for one contact and its drive per volt: with an equipotential driving layer,
  /// (K + C)·u = E·C·1 on the probing dofs; with a resistive one, the coupled system.
  CoupledSystem system_for(const ContactLoad& contact) const {
    if (driving) return driving->system(contact);
    // C touches only couplings within triangles, so F keeps the stiffness's pattern.
    const SparseMatrix C = contact_to_dof_space(mesh, contact, dofs);
    return {stiffness_dof + C, C * Vector::Ones(dofs.dof_count)};
  }

  /// Dof potentials, dof_count by N: column l is the solution with electrode l grounded.
  Matrix solve_dofs(const ContactLoad& contact, double E) {
    const int n = dofs.dof_count, N = dofs.electrode_count;
    if (contact.empty()) return Matrix::Zero(n, N);
    const auto [F, drive] = system_for(contact);
    const auto unknowns = static_cast<int>(F.rows());  // n, or n + the driving layer's free nodes
    const SparseMatrix A0 = F.bottomRightCorner(unknowns - 1, unknowns - 1);  // electrode 0 grounded
    if (driving) cholesky.analyze(A0);  // the coupling's pattern follows the contact
    cholesky.factorize(A0);

    Matrix rhs = Matrix::Zero(unknowns - 1, N);  // reduced index r = dof − 1
    rhs.col(0) = drive.tail(unknowns - 1);
    for (int l = 1; l < N; ++l) rhs(l - 1, l) = 1.0;
    const Matrix X = cholesky.solve(rhs);  // X.col(0) = a (unit drive), X.col(l) = w_l (unit current at l)

    const Vector f0 = Vector(F.col(0)).tail(unknowns - 1);  // row 0 of F, F symmetric
    const double alpha0 = f0.dot(X.col(0)) - drive[0];
    Matrix U = Matrix::Zero(unknowns, N);
    const auto series = [&](int l) { return series_ohm.empty() ? 0.0 : series_ohm[static_cast<std::size_t>(l)]; };
    if (const double R0 = series(0); R0 > 0) {
      // Electrode 0 grounded through R0: u = c·1 + x·a with x = E − c. The current injected at
      // electrode 0 is x·alpha0 (negative: it drains), and it comes from ground through R0, so
      // −c/R0 = x·alpha0, i.e. E − x = −R0·alpha0·x: x = E / (1 − alpha0·R0).
      const double x = E / (1.0 - alpha0 * R0);
      U.col(0).setConstant(E - x);
      U.col(0).tail(unknowns - 1) += x * X.col(0);
    } else {
      U.col(0).tail(unknowns - 1) = E * X.col(0);
    }
    for (int l = 1; l < N; ++l) {
      // Unknowns x = E − c and I (the current injected at l; −I drains through R_l to ground):
      // u(e_l) = c + x·a_l + I·w_l(l) = −I·R_l; net current at electrode 0 = 0.
      Eigen::Matrix2d M;
      M << X(l - 1, 0) - 1.0, X(l - 1, l) + series(l), alpha0, f0.dot(X.col(l));
      const Eigen::Vector2d xI = M.fullPivLu().solve(Eigen::Vector2d(-E, 0.0));
      const double c = E - xI[0];
      U.col(l).setConstant(c);
      U.col(l).tail(unknowns - 1) += xI[0] * X.col(0) + xI[1] * X.col(l);
    }
    return U.topRows(n);
  }
};

ForwardModel::ForwardModel(Mesh mesh, double sheet_resistance_ohm_per_sq) : impl_(std::make_unique<Impl>()) {
  if (!(sheet_resistance_ohm_per_sq > 0)) throw InvalidInput("sheet resistance must be positive");
  impl_->set_mesh(std::move(mesh));
  impl_->assemble(Vector::Constant(impl_->mesh.triangle_count(), 1.0 / sheet_resistance_ohm_per_sq));
}

ForwardModel::ForwardModel(Mesh mesh, const Vector& element_conductance_S, const std::optional<DrivingLayer>& driving)
    : impl_(std::make_unique<Impl>()) {
  impl_->set_mesh(std::move(mesh));
  const auto positive_per_triangle = [&](const Vector& c) {
    return c.size() == impl_->mesh.triangle_count() && c.minCoeff() > 0;
  };
  if (!positive_per_triangle(element_conductance_S))
    throw InvalidInput("sheet conductance: one positive value per triangle is needed");
  impl_->assemble(element_conductance_S);
  if (driving) {
    if (!positive_per_triangle(driving->element_conductance_S))
      throw InvalidInput("driving layer conductance: one positive value per triangle is needed");
    impl_->driving.emplace(impl_->mesh, impl_->dofs, impl_->stiffness_dof, *driving);
  }
}

ForwardModel::~ForwardModel() = default;
ForwardModel::ForwardModel(ForwardModel&&) noexcept = default;
ForwardModel& ForwardModel::operator=(ForwardModel&&) noexcept = default;

const Mesh& ForwardModel::mesh() const { return impl_->mesh; }
int ForwardModel::electrode_count() const { return impl_->dofs.electrode_count; }

void ForwardModel::set_series_resistance(std::vector<double> ohm) {
  if (!ohm.empty() && static_cast<int>(ohm.size()) != electrode_count())
    throw InvalidInput("series resistance: " + std::to_string(ohm.size()) + " values for " +
                       std::to_string(electrode_count()) + " electrodes");
  for (const double r : ohm)
    if (!(r >= 0) || !std::isfinite(r)) throw InvalidInput("series resistance must be finite and >= 0 ohm");
  impl_->series_ohm = std::move(ohm);
}

Frame ForwardModel::solve_frame(const ContactLoad& contact, double drive_voltage_V) {
  const int N = electrode_count();
  const Matrix U = impl_->solve_dofs(contact, drive_voltage_V);
  Frame frame = U.topRows(N).transpose();  // frame(l, m) = potential of electrode m, ground l
  // Through a series resistance the grounded electrode's sheet side is above 0 V, but the board
  // reads its grounded line.
  if (!impl_->series_ohm.empty()) frame.diagonal().setZero();
  return frame;
}

Matrix ForwardModel::solve_potentials(const ContactLoad& contact, double drive_voltage_V) {
  const Matrix U = impl_->solve_dofs(contact, drive_voltage_V);
  Matrix nodal(impl_->mesh.node_count(), electrode_count());
  for (Index v = 0; v < nodal.rows(); ++v) nodal.row(v) = U.row(impl_->dofs.dof_of_node[v]);
  return nodal;
}

}  // namespace emit
