#include "emit/fem/forward_model.hpp"

#include <cmath>
#include <optional>
#include <string>

#include <Eigen/Dense>

#include "emit/core/errors.hpp"
#include "emit/fem/condensed_contact_solver.hpp"
#include "emit/fem/driving_layer.hpp"
#include "emit/fem/electrode_dofs.hpp"
#include "emit/fem/sparse_cholesky.hpp"
#include "emit/fem/stiffness.hpp"

namespace emit {

namespace {
constexpr double default_cells_edges = 12;  // a cell's edge in mean edge lengths: ~150 dofs a cell
}  // namespace

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

  /// How every grounding's field follows from the electrode-0-grounded solutions X (column 0: a,
  /// the unit drive's; column l: w_l, a unit current drained at electrode l): with ground l,
  /// u = c_l·1 + x_l·a + y_l·w_l (y_0 = 0). `Xe`: X's rows of electrodes 1…N−1; `f0X`: row 0 of the
  /// system (F's, electrode 0's currents) times each column of X; `drive0`: the drive at electrode 0.
  struct Regrounding {
    Vector c, x, y;
  };
  Regrounding reground(const Matrix& Xe, const Vector& f0X, double drive0, double E) const {
    const int N = dofs.electrode_count;
    Regrounding g{Vector(N), Vector(N), Vector::Zero(N)};
    const double alpha0 = f0X[0] - drive0;
    const auto series = [&](int l) { return series_ohm.empty() ? 0.0 : series_ohm[static_cast<std::size_t>(l)]; };
    // Electrode 0 grounded through R0: u = c·1 + x·a with x = E − c. The current injected at
    // electrode 0 is x·alpha0 (negative: it drains), and it comes from ground through R0, so
    // −c/R0 = x·alpha0, i.e. E − x = −R0·alpha0·x: x = E / (1 − alpha0·R0) (x = E with no R0).
    g.x[0] = E / (1.0 - alpha0 * series(0));
    g.c[0] = E - g.x[0];
    for (int l = 1; l < N; ++l) {
      // Unknowns x = E − c and I (the current injected at l; −I drains through R_l to ground):
      // u(e_l) = c + x·a_l + I·w_l(l) = −I·R_l; net current at electrode 0 = 0.
      Eigen::Matrix2d M;
      M << Xe(l - 1, 0) - 1.0, Xe(l - 1, l) + series(l), alpha0, f0X[l];
      const Eigen::Vector2d xI = M.fullPivLu().solve(Eigen::Vector2d(-E, 0.0));
      g.c[l] = E - xI[0];
      g.x[l] = xI[0];
      g.y[l] = xI[1];
    }
    return g;
  }

  /// The electrode-0-grounded solutions X of (F without dof 0) X = [drive, unit currents at
  /// electrodes 1…N−1] (reduced index r = dof − 1), with F's row 0 and the drive at dof 0.
  struct Solutions {
    Matrix X;
    Vector f0;
    double drive0 = 0;
  };
  Solutions solve_grounded(const ContactLoad& contact) {
    const int N = dofs.electrode_count;
    const auto [F, drive] = system_for(contact);
    const auto unknowns = static_cast<int>(F.rows());  // n, or n + the driving layer's free nodes
    const SparseMatrix A0 = F.bottomRightCorner(unknowns - 1, unknowns - 1);  // electrode 0 grounded
    if (driving) cholesky.analyze(A0);  // the coupling's pattern follows the contact
    cholesky.factorize(A0);
    Matrix rhs = Matrix::Zero(unknowns - 1, N);
    rhs.col(0) = drive.tail(unknowns - 1);
    for (int l = 1; l < N; ++l) rhs(l - 1, l) = 1.0;
    return {cholesky.solve(rhs), Vector(F.col(0)).tail(unknowns - 1), drive[0]};  // row 0 of F, F symmetric
  }

  /// Dof potentials, dof_count by N: column l is the solution with electrode l grounded.
  Matrix solve_dofs(const ContactLoad& contact, double E) {
    const int n = dofs.dof_count, N = dofs.electrode_count;
    if (contact.empty()) return Matrix::Zero(n, N);
    const Solutions s = solve_grounded(contact);
    const Regrounding g = reground(s.X.topRows(N - 1), s.X.transpose() * s.f0, s.drive0, E);
    Matrix U(n, N);
    for (int l = 0; l < N; ++l) {
      U(0, l) = g.c[l];
      U.col(l).tail(n - 1) = (g.c[l] + g.x[l] * s.X.col(0).head(n - 1).array()).matrix();
      if (l > 0) U.col(l).tail(n - 1) += g.y[l] * s.X.col(l).head(n - 1);
    }
    return U;
  }

  /// The frame: electrode m's potential with electrode l grounded, frame(l, m).
  Frame solve_frame(const ContactLoad& contact, double E) {
    const int N = dofs.electrode_count;
    if (contact.empty()) return Frame::Zero(N, N);
    if (condensed) return condensed_frame(contact, E);
    const Matrix U = solve_dofs(contact, E);
    return U.topRows(N).transpose();
  }

  /// Condensation (condensed_contact_solver.hpp): the kept dofs are electrodes 1…N−1 (reduced
  /// 0…N−2, the unit currents' places) and electrode 0's neighbours (row 0 of F lives there).
  struct Condensed {
    CondensedContactSolver solver;
    std::vector<int> kept_of_reduced;  ///< per reduced dof: its place among the kept, −1 if not kept
    Vector f0_stiffness;               ///< K's row 0 on the kept dofs
    std::vector<CondensedContactSolver::Entry> entries;
    std::vector<std::pair<int, double>> drive;
    Vector f0;
    Matrix X;
  };
  std::optional<Condensed> condensed;

  void condense(double cell_size_mm) {
    const int n = dofs.dof_count, N = dofs.electrode_count;
    std::vector<int> kept;
    for (int l = 1; l < N; ++l) kept.push_back(l - 1);
    for (SparseMatrix::InnerIterator it(stiffness_dof, 0); it; ++it)
      if (it.row() >= N) kept.push_back(static_cast<int>(it.row()) - 1);
    std::vector<int> units(static_cast<std::size_t>(N - 1));
    for (int l = 1; l < N; ++l) units[static_cast<std::size_t>(l - 1)] = l - 1;
    std::vector<Vector3> position(static_cast<std::size_t>(n - 1), Vector3::Zero());
    double edge_mm = 0;
    for (Index t = 0; t < mesh.triangle_count(); ++t)
      for (int k = 0; k < 3; ++k)
        edge_mm += (mesh.nodes_mm.row(mesh.triangles(t, k)) - mesh.nodes_mm.row(mesh.triangles(t, (k + 1) % 3))).norm();
    edge_mm /= 3.0 * static_cast<double>(mesh.triangle_count());
    for (Index v = 0; v < mesh.node_count(); ++v)
      if (const int d = dofs.dof_of_node[static_cast<std::size_t>(v)]; d > 0)
        position[static_cast<std::size_t>(d - 1)] = mesh.nodes_mm.row(v).transpose();
    const SparseMatrix A0 = stiffness_dof.bottomRightCorner(n - 1, n - 1);
    std::vector<int> kept_of_reduced(static_cast<std::size_t>(n - 1), -1);
    Vector f0_stiffness = Vector::Zero(static_cast<Index>(kept.size()));
    for (std::size_t k = 0; k < kept.size(); ++k) {
      kept_of_reduced[static_cast<std::size_t>(kept[k])] = static_cast<int>(k);
      f0_stiffness[static_cast<Index>(k)] = stiffness_dof.coeff(kept[k] + 1, 0);
    }
    condensed.emplace(Condensed{CondensedContactSolver(A0, position, std::move(kept), std::move(units),
                                                       cell_size_mm > 0 ? cell_size_mm : default_cells_edges * edge_mm),
                                std::move(kept_of_reduced),
                                std::move(f0_stiffness),
                                {},
                                {},
                                {},
                                {}});
  }

  Frame condensed_frame(const ContactLoad& contact, double E) {
    const int N = dofs.electrode_count;
    Condensed& c = *condensed;
    c.entries.clear();
    c.drive.clear();
    c.f0 = c.f0_stiffness;
    double drive0 = 0;
    for (std::size_t i = 0; i < contact.triangles.size(); ++i) {
      const auto v = mesh.triangles.row(contact.triangles[i]);
      for (int a = 0; a < 3; ++a) {
        const int da = dofs.dof_of_node[static_cast<std::size_t>(v[a])];
        for (int b = 0; b < 3; ++b) {
          const int db = dofs.dof_of_node[static_cast<std::size_t>(v[b])];
          const double value = contact.local_S[i](a, b);
          if (da == 0) drive0 += value;
          else c.drive.emplace_back(da - 1, value);
          if (da == 0 && db != 0) c.f0[c.kept_of_reduced[static_cast<std::size_t>(db - 1)]] += value;
          if (da != 0 && db != 0) c.entries.emplace_back(da - 1, db - 1, value);
        }
      }
    }
    c.solver.solve(c.entries, c.drive, c.X);
    const Regrounding g = reground(c.X.topRows(N - 1), c.X.transpose() * c.f0, drive0, E);
    Frame frame(N, N);
    for (int l = 0; l < N; ++l) {
      frame(l, 0) = g.c[l];
      for (int m = 1; m < N; ++m)
        frame(l, m) = g.c[l] + g.x[l] * c.X(m - 1, 0) + (l > 0 ? g.y[l] * c.X(m - 1, l) : 0.0);
    }
    return frame;
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
  Frame frame = impl_->solve_frame(contact, drive_voltage_V);  // frame(l, m) = potential of electrode m, ground l
  // Through a series resistance the grounded electrode's sheet side is above 0 V, but the board
  // reads its grounded line.
  if (!impl_->series_ohm.empty()) frame.diagonal().setZero();
  return frame;
}

void ForwardModel::condense_contacts(double cell_size_mm) {
  if (impl_->driving)
    throw InvalidInput("condensed frames: not with a resistive driving layer (its coupling follows the contact)");
  if (!(cell_size_mm >= 0) || !std::isfinite(cell_size_mm))
    throw InvalidInput("condensed frames: the cell size must be 0 (automatic) or positive");
  impl_->condense(cell_size_mm);
}

bool ForwardModel::condensed() const { return impl_->condensed.has_value(); }
int ForwardModel::condensed_skeleton_size() const {
  return impl_->condensed ? impl_->condensed->solver.skeleton_size() : 0;
}

Matrix ForwardModel::solve_potentials(const ContactLoad& contact, double drive_voltage_V) {
  const Matrix U = impl_->solve_dofs(contact, drive_voltage_V);
  Matrix nodal(impl_->mesh.node_count(), electrode_count());
  for (Index v = 0; v < nodal.rows(); ++v) nodal.row(v) = U.row(impl_->dofs.dof_of_node[v]);
  return nodal;
}

}  // namespace emit
