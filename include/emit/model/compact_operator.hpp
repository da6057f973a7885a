#pragma once
/// \file compact_operator.hpp
/// The reconstruction operator R (#F by M, paper eq. 7) in the form the per-frame path applies:
/// truncated to the singular values that matter and stored in single precision as two factors,
///   R ≈ A·B,   A = U_k S_k (#F by k),   B = V_kᵀ (k by M),
/// so a frame costs k(#F + M) multiply-adds instead of #F·M, on half the bytes. R's singular
/// values fall fast (the regularisation filters the data's small ones): on the default sensor k is
/// about 100 of M = 240. The products run in BLAS (sgemv), which picks the CPU's widest vector
/// instructions at run time.
///
/// Beside the factors it keeps P = (J Q⁻¹ Jᵀ + λ² I)⁻¹ (M by M, float), the precision of the
/// operator's Gaussian prior on δV: readings a frame cannot be trusted with are filled by their
/// mean given the others under it (frame/masked_readings.hpp), which makes the image exactly the
/// one an operator built without them would give.
#include <Eigen/Core>

#include "emit/core/types.hpp"

namespace emit {

/// Per-caller scratch for CompactOperator::apply, so the operator is shared read-only.
struct CompactOperatorScratch {
  Eigen::VectorXf data, coefficients, image;
};

class CompactOperator {
 public:
  CompactOperator() = default;
  /// From its factors, as OperatorFamily::compact_operator_for builds them (without forming R)
  /// and the cache stores them. \throw InvalidInput if their sizes do not match.
  /// `precision`: P above, M by M, or empty (no reading can then be masked).
  CompactOperator(Eigen::MatrixXf left, Eigen::MatrixXf right, double truncation_bound, double largest_singular_value,
                  double lambda2 = 0, Eigen::MatrixXf precision = {});

  /// Scratch already sized for this operator.
  CompactOperatorScratch scratch() const;
  /// image = A·(B·δV). Allocates nothing once `scratch` has been used with this operator.
  void apply(const Vector& dV, Vector& image, CompactOperatorScratch& scratch) const;

  Index rows() const { return left_.rows(); }
  Index cols() const { return right_.cols(); }
  Index rank() const { return right_.rows(); }
  /// s_{k+1}/s₁: the bound on the truncation's change to an image, relative to s₁‖δV‖.
  double truncation_bound() const { return truncation_bound_; }
  /// s₁, R's largest singular value.
  double largest_singular_value() const { return largest_singular_value_; }
  /// The λ² it was built with (0 when not told).
  double lambda2() const { return lambda2_; }
  /// ‖row k of R‖ for each element k, computed from A: B's rows are orthonormal, so R's row k has
  /// A's row k's norm. An image's noise per element is σ(δV)·‖row k‖ for white reading noise.
  Vector row_norms() const;
  const Eigen::MatrixXf& left() const { return left_; }    ///< A, #F by k
  const Eigen::MatrixXf& right() const { return right_; }  ///< B, k by M
  /// P = (J Q⁻¹ Jᵀ + λ² I)⁻¹, M by M; empty when not built with it.
  const Eigen::MatrixXf& precision() const { return precision_; }

 private:
  Eigen::MatrixXf left_;   ///< A = U_k S_k, column-major #F by k
  Eigen::MatrixXf right_;  ///< B = V_kᵀ, column-major k by M
  Eigen::MatrixXf precision_;
  double truncation_bound_ = 0, largest_singular_value_ = 0, lambda2_ = 0;
};

}  // namespace emit
