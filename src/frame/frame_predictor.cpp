#include "emit/frame/frame_predictor.hpp"

#include <cmath>
#include <string>
#include <utility>

#include "emit/core/errors.hpp"

namespace emit {

FramePredictor::FramePredictor(const Mesh& mesh, const DenseGreenFunction& green)
    : mesh_(mesh),
      green_(green),
      patch_of_dof_(green.dofs.dof_count, -1),
      previous_patch_of_dof_(green.dofs.dof_count, -1) {}

void FramePredictor::set_series_resistance(const std::vector<double>& ohm) {
  const int N = green_.dofs.electrode_count;
  if (!ohm.empty() && static_cast<int>(ohm.size()) != N)
    throw InvalidInput("series resistance: " + std::to_string(ohm.size()) + " values for " + std::to_string(N) +
                       " electrodes");
  for (double r : ohm)
    if (!(std::isfinite(r) && r >= 0)) throw InvalidInput("series resistance: must be finite and not negative");
  series_ohm_ = ohm;
}

/// Numbers the dofs the contact touches; the last call's numbering is kept beside it.
void FramePredictor::gather_patch(const std::vector<Index>& triangles) {
  std::swap(patch_of_dof_, previous_patch_of_dof_);
  std::swap(patch_dofs_, previous_patch_dofs_);
  for (int dof : patch_dofs_) patch_of_dof_[dof] = -1;  // the numbering before the last
  patch_dofs_.clear();
  for (Index t : triangles)
    for (int k = 0; k < 3; ++k) {
      const int dof = green_.dofs.dof_of_node[mesh_.triangles(t, k)];
      if (patch_of_dof_[dof] < 0) {
        patch_of_dof_[dof] = static_cast<int>(patch_dofs_.size());
        patch_dofs_.push_back(dof);
      }
    }
}

/// G0 on the patch. G0 is ~180 MB: its entries on a patch of p dofs are p² cache misses (a third
/// of a four-contact frame's time), while a fit's next evaluation mostly touches the same dofs. So
/// what the last patch had is copied from the last G_pp and only the new dofs' entries read.
void FramePredictor::gather_green() {
  const auto p = static_cast<Index>(patch_dofs_.size());
  const int N = green_.dofs.electrode_count;
  std::swap(G_pp_, previous_G_pp_);
  G_pp_.resize(p, p);
  for (Index j = 0; j < p; ++j) {
    const int previous_j = previous_patch_of_dof_[patch_dofs_[j]];
    const auto column = green_.column(patch_dofs_[j]);
    for (Index i = 0; i < p; ++i) {
      const int previous_i = previous_j < 0 ? -1 : previous_patch_of_dof_[patch_dofs_[i]];
      G_pp_(i, j) = previous_i < 0 ? column[green_.row(patch_dofs_[i])] : previous_G_pp_(previous_i, previous_j);
    }
  }
  G_pe_.resize(p, N);
  for (int e = 0; e < N; ++e) {
    const auto column = green_.column(e);
    for (Index i = 0; i < p; ++i) G_pe_(i, e) = column[green_.row(patch_dofs_[i])];
  }
}

void FramePredictor::predict(const std::vector<Index>& triangles, const std::vector<Eigen::Matrix3d>& local_S,
                             double drive_voltage_V, Frame& frame) {
  const double E = drive_voltage_V;
  const int N = green_.dofs.electrode_count;  // electrode e is dof e
  frame.setZero(N, N);
  gather_patch(triangles);  // empty: derivative() then gives 0
  if (triangles.empty()) return;
  gather_green();
  const auto p = static_cast<Index>(patch_dofs_.size());
  // C on the patch, dense: its products below go to BLAS. A loop over the triangles' sparse
  // entries instead took the realistic round's calibration from 56 s to 100 s (a run of each side
  // by side) and four-contact frames 7 % faster: kept dense.
  C_.setZero(p, p);
  for (std::size_t i = 0; i < triangles.size(); ++i)
    for (int a = 0; a < 3; ++a)
      for (int b = 0; b < 3; ++b)
        C_(patch_of_dof_[green_.dofs.dof_of_node[mesh_.triangles(triangles[i], a)]],
           patch_of_dof_[green_.dofs.dof_of_node[mesh_.triangles(triangles[i], b)]]) += local_S[i](a, b);
  c1_.noalias() = C_.rowwise().sum();  // C·1: the contact's pull per volt of drive
  M_.setIdentity(p, p);
  M_.noalias() += C_ * G_pp_;
  lu_.compute(M_);
  adjoint_ready_ = false;
  Y_.resize(p, N);  // column 0: unit drive; column l: unit current into electrode l
  Y_.col(0) = c1_;
  Y_.rightCols(N - 1).noalias() = C_ * G_pe_.rightCols(N - 1);
  Y_ = lu_.solve(Y_);
  Z_p_.noalias() = G_pp_ * Y_;
  Z_e_.noalias() = G_pe_.transpose() * Y_;

  // Ground 0: the unit-drive field a = G0_·P M⁻¹ C·1. The contact feeds x·D into the sheet (x
  // the drive across it, D per volt), all of which leaves through electrode 0 and its series
  // resistance R0, lifting the sheet by c = R0·x·D; c + x = E gives x = E / (1 + R0·D).
  const auto a_p = Z_p_.col(0);
  const auto a_e = Z_e_.col(0);
  const double drawn_by_a = c1_.sum() - c1_.dot(a_p);  // current the contact feeds in, unit drive
  const double R0 = series_ohm_.empty() ? 0.0 : series_ohm_[0];
  const double x0 = E / (1.0 + R0 * drawn_by_a);
  frame.row(0) = (Vector::Constant(N, E - x0) + x0 * a_e).transpose();
  E_ = E, drawn_by_a_ = drawn_by_a, x0_ = x0;
  Q_.resize(p, N);
  Q_.col(0) = Vector::Ones(p) - a_p;
  Q_.rightCols(N - 1) = G_pe_.rightCols(N - 1) - Z_p_.rightCols(N - 1);  // w_l on the patch
  Qt_ = Q_.transpose();
  W_e_.resize(N, N);
  regrounding_.resize(N);
  xI_.resize(N);
  for (int l = 1; l < N; ++l) {
    // w_l = (A0 + C)⁻¹ e_l on the electrodes and the patch.
    W_e_.col(l) = green_.column(l).head(N) - Z_e_.col(l);
    const auto w_e = W_e_.col(l);
    const double lost_through_contact = c1_.dot(Q_.col(l));  // −(contact inflow)
    // Unknowns x = E − c and I (see forward_model.hpp): u(e_l) = c + x a_l + I w_l(l) = −I·R_l
    // (the current I into electrode l is −I out of it, through R_l to ground), and no net
    // current at electrode 0: x · drawn_by_a + I · (1 − lost_through_contact) = 0.
    const double Rl = series_ohm_.empty() ? 0.0 : series_ohm_[static_cast<std::size_t>(l)];
    Eigen::Matrix2d A;
    A << a_e[l] - 1.0, w_e[l] + Rl, drawn_by_a, 1.0 - lost_through_contact;
    const Eigen::Vector2d xI = A.partialPivLu().solve(Eigen::Vector2d(-E, 0.0));
    regrounding_[l] = A, xI_[l] = xI;
    const double c = E - xI[0];
    frame.row(l) = (Vector::Constant(N, c) + xI[0] * a_e + xI[1] * w_e).transpose();
  }
}

void FramePredictor::derivative(const std::vector<Index>& triangles, const std::vector<Eigen::Matrix3d>& d_local_S,
                                Frame& d_frame) {
  const int N = green_.dofs.electrode_count;
  d_frame.setZero(N, N);
  if (patch_dofs_.empty()) return;
  const auto p = static_cast<Index>(patch_dofs_.size());
  if (!adjoint_ready_) {
    // dY = M⁻¹ dC Q is only ever seen through G_peᵀ dY (the electrodes) and c1ᵀ G_pp dY (the
    // contact's currents): one transposed solve for [G_pe, G_pp c1] per predict() leaves each
    // direction O(p·N²) instead of the solve's O(p²·N).
    adjoint_.resize(p, N + 1);
    adjoint_.leftCols(N) = G_pe_;
    adjoint_.col(N).noalias() = G_pp_ * c1_;  // G_pp symmetric: (c1ᵀ G_pp)ᵀ
    adjoint_ = lu_.transpose().solve(adjoint_);
    adjoint_ready_ = true;
  }
  // (dC Q)ᵀ and dC·1 straight from the triangles' matrices (dC is sparse on the patch), a column
  // of Qᵀ at a time.
  dCQt_.setZero(N, p);
  dc1_.setZero(p);
  for (std::size_t i = 0; i < triangles.size(); ++i)
    for (int a = 0; a < 3; ++a) {
      const int row = patch_of_dof_[green_.dofs.dof_of_node[mesh_.triangles(triangles[i], a)]];
      for (int b = 0; b < 3; ++b) {
        const double s = d_local_S[i](a, b);
        if (s == 0) continue;
        dCQt_.col(row) += s * Qt_.col(patch_of_dof_[green_.dofs.dof_of_node[mesh_.triangles(triangles[i], b)]]);
        dc1_[row] += s;
      }
    }
  dZ_e_.noalias() = (dCQt_ * adjoint_.leftCols(N)).transpose();
  c1_dZ_p_.noalias() = dCQt_ * adjoint_.col(N);  // c1ᵀ dZ_p, per column
  const auto a_p = Z_p_.col(0);
  const auto a_e = Z_e_.col(0);
  const auto da_e = dZ_e_.col(0);
  const double d_drawn = dc1_.sum() - dc1_.dot(a_p) - c1_dZ_p_[0];
  // x0 = E / (1 + R0·D): dx0 = −E·R0·dD / (1 + R0·D)²; row 0 = (E − x0) + x0·a.
  const double R0 = series_ohm_.empty() ? 0.0 : series_ohm_[0];
  const double dx0 = -E_ * R0 * d_drawn / ((1.0 + R0 * drawn_by_a_) * (1.0 + R0 * drawn_by_a_));
  d_frame.row(0) = (Vector::Constant(N, -dx0) + dx0 * a_e + x0_ * da_e).transpose();
  for (int l = 1; l < N; ++l) {
    const auto dw_e = -dZ_e_.col(l);  // w_l = G0·l − Z·l
    const double d_lost = dc1_.dot(Q_.col(l)) - c1_dZ_p_[l];
    Eigen::Matrix2d dA;
    dA << da_e[l], dw_e[l], d_drawn, -d_lost;
    const Eigen::Vector2d d_xI = -regrounding_[l].partialPivLu().solve(dA * xI_[l]);
    const Eigen::Vector2d& xI = xI_[l];
    d_frame.row(l) =
        (Vector::Constant(N, -d_xI[0]) + d_xI[0] * a_e + xI[0] * da_e + d_xI[1] * W_e_.col(l) + xI[1] * dw_e)
            .transpose();
  }
}

}  // namespace emit
