#include "emit/model/compact_operator.hpp"

#include <cblas.h>

#include "emit/core/errors.hpp"

namespace emit {

CompactOperator::CompactOperator(Eigen::MatrixXf left, Eigen::MatrixXf right, double truncation_bound,
                                 double largest_singular_value, double lambda2, Eigen::MatrixXf precision)
    : left_(std::move(left)),
      right_(std::move(right)),
      precision_(std::move(precision)),
      truncation_bound_(truncation_bound),
      largest_singular_value_(largest_singular_value),
      lambda2_(lambda2) {
  if (left_.cols() != right_.rows())
    throw InvalidInput("compact operator: factors of " + std::to_string(left_.cols()) + " and " +
                       std::to_string(right_.rows()) + " singular values");
  if (precision_.size() > 0 && (precision_.rows() != right_.cols() || precision_.cols() != right_.cols()))
    throw InvalidInput("compact operator: a precision of " + std::to_string(precision_.rows()) + " by " +
                       std::to_string(precision_.cols()) + " for " + std::to_string(right_.cols()) + " readings");
}

Vector CompactOperator::row_norms() const { return left_.cast<double>().rowwise().norm(); }

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
