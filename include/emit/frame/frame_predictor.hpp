#pragma once
/// \file frame_predictor.hpp
/// The frame a small contact gives, from the dense Green's function (green_function.hpp) by
/// Woodbury on the contact's patch: the same frame ForwardModel::solve_frame gives (equipotential
/// driving layer), for O(p³ + p·N²) work on the p dofs the contact touches instead of a sparse
/// factorisation of the whole sheet.
///
/// With ground 0, A0 + C differs from A0 on the patch only, so (A0 + C)⁻¹ = G0 − G0_P M⁻¹ C G0_P·,
/// M = I + C G0_PP. That gives the unit-drive field a and the unit-current fields w_l on the patch
/// and the electrodes; each other grounding is then the 2×2 regrounding of forward_model.hpp,
/// written with the currents the contact carries (conservation instead of a row of the matrix).
#include <vector>

#include <Eigen/Dense>

#include "emit/fem/forward_model.hpp"
#include "emit/model/green_function.hpp"

namespace emit {

class FramePredictor {
 public:
  /// Keeps references to both, which must outlive it.
  FramePredictor(const Mesh& mesh, const DenseGreenFunction& green);

  /// Each electrode's series resistance [Ω] (electrode contact + the multiplexer's switch; README,
  /// "Sensor description"): the grounded electrode l reaches ground through R_l, so its sheet-side
  /// potential is the current it drains times R_l instead of 0 (a sensing electrode draws no
  /// current: its reading is its potential). Empty or all 0: ideal grounds. \throw InvalidInput
  /// for a wrong count or a negative or non-finite value.
  void set_series_resistance(const std::vector<double>& ohm);

  /// The frame (N×N, ground-major, already sized) of a contact given as touched triangles and
  /// their 3×3 contact matrices [S], with the driving layer at `drive_voltage_V`.
  void predict(const std::vector<Index>& triangles, const std::vector<Eigen::Matrix3d>& local_S, double drive_voltage_V,
               Frame& frame);

  /// After predict(): the frame's derivative along a change dC of the contact matrices of the
  /// same triangles (d_local_S[i] for triangles[i]), by differentiating the Woodbury solve and
  /// the 2×2 regrounding: dY = M⁻¹ dC Q, Q = [1 − a, w_1 … w_{N−1}] on the patch, seen through
  /// the adjoint M⁻ᵀ[G_pe, G_pp c1] (solved once after each predict): O(p·N²) a direction.
  void derivative(const std::vector<Index>& triangles, const std::vector<Eigen::Matrix3d>& d_local_S, Frame& d_frame);

 private:
  void gather_patch(const std::vector<Index>& triangles);
  void gather_green();
  const Mesh& mesh_;
  const DenseGreenFunction& green_;
  std::vector<int> patch_of_dof_;  ///< −1 off the patch
  std::vector<int> patch_dofs_;
  std::vector<int> previous_patch_of_dof_, previous_patch_dofs_;  ///< the last predict()'s patch
  Matrix previous_G_pp_;                                          ///< and G0 on it
  Matrix C_, G_pp_, G_pe_, M_, Y_, Z_p_, Z_e_;
  Vector c1_;
  // Kept from predict() for derivative(): the fields on the patch (Q) and the electrodes, and per
  // grounding l the 2×2 system and its solution.
  double E_ = 0, drawn_by_a_ = 0, x0_ = 0;  ///< x0_: the drive across the sheet with ground 0
  std::vector<double> series_ohm_;          ///< per electrode; empty: none
  Matrix Q_, W_e_;                          ///< W_e_.col(l) = w_l on the electrodes
  std::vector<Eigen::Matrix2d> regrounding_;
  std::vector<Eigen::Vector2d> xI_;
  Matrix adjoint_;  ///< M⁻ᵀ [G_pe, G_pp c1], on the first derivative() after a predict()
  bool adjoint_ready_ = false;
  Matrix Qt_, dCQt_, dZ_e_;  ///< Qt_ = Qᵀ, for derivative()'s columns
  Vector dc1_, c1_dZ_p_;
  Eigen::PartialPivLU<Matrix> lu_;
};

}  // namespace emit
