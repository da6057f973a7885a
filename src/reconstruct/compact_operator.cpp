#include "emit/reconstruct/compact_operator.hpp"

#include <cblas.h>

#include <Eigen/Eigenvalues>

#include "emit/errors.hpp"

namespace emit {

CompactOperator::CompactOperator(const Matrix& op, double relative_cutoff) {
  if (!(relative_cutoff >= 0 && relative_cutoff < 1))
    throw InvalidInput("the operator's rank cutoff must be in [0, 1), got " + std::to_string(relative_cutoff));
  // R = U S Vᵀ from the small M×M eigenproblem RᵀR = V S² Vᵀ; squaring costs precision only
  // below ~1e-8 of s₁, far under any cutoff worth using.
  const Eigen::SelfAdjointEigenSolver<Matrix> eigen(op.transpose() * op);
  const Vector s = eigen.eigenvalues().reverse().cwiseMax(0.0).cwiseSqrt();  // descending
  const Matrix V = eigen.eigenvectors().rowwise().reverse();
  largest_singular_value_ = s.size() > 0 ? s[0] : 0.0;
  Index k = 0;
  while (k < s.size() && s[k] > relative_cutoff * largest_singular_value_) ++k;
  truncation_bound_ = k < s.size() && largest_singular_value_ > 0 ? s[k] / largest_singular_value_ : 0.0;
  left_ = (op * V.leftCols(k)).cast<float>();
  right_ = V.leftCols(k).transpose().cast<float>();
}

CompactOperator::CompactOperator(Eigen::MatrixXf left, Eigen::MatrixXf right, double truncation_bound,
                                 double largest_singular_value)
    : left_(std::move(left)),
      right_(std::move(right)),
      truncation_bound_(truncation_bound),
      largest_singular_value_(largest_singular_value) {
  if (left_.cols() != right_.rows())
    throw InvalidInput("compact operator: factors of " + std::to_string(left_.cols()) + " and " +
                       std::to_string(right_.rows()) + " singular values");
}

CompactOperatorScratch CompactOperator::scratch() const {
  return {Eigen::VectorXf(cols()), Eigen::VectorXf(rank()), Eigen::VectorXf(rows())};
}

void CompactOperator::apply(const Vector& dV, Vector& image, CompactOperatorScratch& scratch) const {
  if (dV.size() != cols())
    throw InvalidInput("frame difference has " + std::to_string(dV.size()) + " values, the operator expects " +
                       std::to_string(cols()));
  scratch.data.resize(cols());
  scratch.coefficients.resize(rank());
  scratch.image.resize(rows());
  image.resize(rows());
  scratch.data = dV.cast<float>();
  const auto m = static_cast<int>(rows()), n = static_cast<int>(cols()), k = static_cast<int>(rank());
  if (k == 0) {
    image.setZero();
    return;
  }
  cblas_sgemv(CblasColMajor, CblasNoTrans, k, n, 1.0f, right_.data(), k, scratch.data.data(), 1, 0.0f,
              scratch.coefficients.data(), 1);
  cblas_sgemv(CblasColMajor, CblasNoTrans, m, k, 1.0f, left_.data(), m, scratch.coefficients.data(), 1, 0.0f,
              scratch.image.data(), 1);
  image = scratch.image.cast<double>();
}

}  // namespace emit
