#pragma once
/// \file reconstruction_operator.hpp
/// The linear reconstruction operator of paper eq. 7, δφ = (JᵀJ + λ²Q)⁻¹ Jᵀ δV, built in
/// measurement space so no K×K matrix is ever formed or inverted (docs/physics.md, "The linear methods per frame"):
///   R = Q⁻¹Jᵀ (J Q⁻¹ Jᵀ + λ² I)⁻¹,
/// an (M×M) solve for M measurements. Per frame it is one matrix–vector product.
#include <string>

#include "emit/core/types.hpp"
#include "emit/mesh/mesh.hpp"
#include "emit/model/compact_operator.hpp"

namespace emit {

enum class Prior {
  identity,   ///< Q = I: the paper's choice
  noser,      ///< Q = diag(JᵀJ)^p (Cheney et al.'s NOSER; p = noser_exponent)
  laplacian,  ///< Q = LᵀL + εI, L the element graph Laplacian (edge neighbours): smooth images
};

struct OperatorOptions {
  Prior prior = Prior::identity;
  /// λ², or 0 (the default) to choose it from the spectrum of J Q⁻¹ Jᵀ: relative_lambda2 times
  /// its second eigenvalue (model/lambda_rule.hpp). The paper chose its λ² = 1000 by
  /// L-curve and positional error (§3.1) for its own Jacobian's scale; a fixed λ² does not carry
  /// over between sheets, whose Jacobians' scales differ ~20×.
  double lambda2 = 0;
  /// λ²/spectrum_scale when lambda2 is 0: the prior's, as `emit eval` measured it (model/method.hpp).
  double relative_lambda2 = 1.63;
  double noser_exponent = 0.5;  ///< p for the NOSER prior
  /// Per frame, R is applied truncated to its singular values above this fraction of the
  /// largest (compact_operator.hpp); 0 keeps them all.
  double rank_cutoff = 1.0 / 4096;
  void validate() const;  ///< \throw InvalidInput naming the option (core/option_check.hpp)
};

std::string prior_name(Prior prior);

/// The dense operator R. \param J  M by #F Jacobian (jacobian.hpp). \return #F by M.
/// λ² = 0 chooses it (OperatorOptions::lambda2). \throw InvalidInput for a negative λ². For tests and baselines: the
/// per-frame path uses build_compact_operator, which never forms R.
Matrix build_reconstruction_operator(const Matrix& J, const Mesh& mesh, const OperatorOptions& options);

/// R truncated at options.rank_cutoff (compact_operator.hpp), built from the eigendecomposition
/// without forming R. Takes J by value so that a caller that moves it in holds one #F·M matrix.
CompactOperator build_compact_operator(Matrix J, const Mesh& mesh, const OperatorOptions& options);

/// The operators of one Jacobian and prior for every λ: the λ-independent work (Q⁻¹Jᵀ and the
/// eigendecomposition J Q⁻¹ Jᵀ = U Σ Uᵀ) is done once, so R(λ) = Q⁻¹Jᵀ U diag(1/(σ + λ²)) Uᵀ
/// costs one product. For λ sweeps and L-curves.
class OperatorFamily {
 public:
  OperatorFamily(Matrix J, const Mesh& mesh, Prior prior, double noser_exponent = 0.5);
  /// R(λ), dense, #F by M.
  Matrix operator_for(double lambda2) const;
  /// R(λ) truncated to its singular values above `relative_cutoff` of the largest. The
  /// default cutoff (OperatorOptions::rank_cutoff), 2⁻¹², bounds what the truncation changes,
  /// ‖(R − A·B) δV‖ ≤ 2⁻¹² s₁ ‖δV‖, at the resolution of a 12-bit ADC (paper §3.1).
  /// \throw InvalidInput for a non-positive λ² or a cutoff outside [0, 1).
  CompactOperator compact_operator_for(double lambda2, double relative_cutoff) const;
  /// options.lambda2, or when it is 0 the automatic choice from the spectrum (lambda_rule.hpp).
  double lambda2_for(const OperatorOptions& options) const;
  /// The eigenvalues σ of J Q⁻¹ Jᵀ, ascending (the data's singular values squared).
  const Vector& eigenvalues() const { return sigma_; }

 private:
  /// Q⁻¹Jᵀ·X (#F by columns of X).
  Matrix prior_inverse_jt_times(const Matrix& X) const;
  /// The same rounded to single precision (the compact operator's factor), computed in double.
  Eigen::MatrixXf prior_inverse_jt_times_in_float(const Matrix& X) const;

  Prior prior_;
  Matrix J_;     ///< M by #F, kept for Q = I (where Q⁻¹Jᵀ = Jᵀ)
  Matrix QiJt_;  ///< Q⁻¹Jᵀ, #F by M, for the other priors
  Matrix U_;     ///< M by M
  Vector sigma_;
  Matrix basis_gram_;  ///< (Q⁻¹JᵀU)ᵀ(Q⁻¹JᵀU) for the other priors (diag(σ) for Q = I)
};

/// #F by #F graph Laplacian of the triangles (two are neighbours when they share an edge).
SparseMatrix element_laplacian(const Mesh& mesh);

}  // namespace emit
