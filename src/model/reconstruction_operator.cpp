#include "emit/model/reconstruction_operator.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <numeric>

#include <Eigen/Dense>

#include "emit/core/errors.hpp"
#include "emit/core/large_matrix.hpp"
#include "emit/core/option_check.hpp"
#include "emit/fem/sparse_cholesky.hpp"
#include "emit/model/lambda_rule.hpp"
#include "emit/model/symmetric_eigen.hpp"

namespace emit {

std::string prior_name(Prior prior) {
  switch (prior) {
    case Prior::identity: return "identity";
    case Prior::noser: return "noser";
    case Prior::laplacian: return "laplacian";
  }
  return "?";
}

SparseMatrix element_laplacian(const Mesh& mesh) {
  std::map<std::array<int, 2>, int> first_triangle_of_edge;
  std::vector<Eigen::Triplet<double, int>> entries;
  Vector degree = Vector::Zero(mesh.triangle_count());
  for (Index t = 0; t < mesh.triangle_count(); ++t)
    for (int k = 0; k < 3; ++k) {
      const int a = mesh.triangles(t, k), b = mesh.triangles(t, (k + 1) % 3);
      const std::array<int, 2> edge{std::min(a, b), std::max(a, b)};
      const auto [it, added] = first_triangle_of_edge.emplace(edge, static_cast<int>(t));
      if (added) continue;
      entries.emplace_back(static_cast<int>(t), it->second, -1.0);
      entries.emplace_back(it->second, static_cast<int>(t), -1.0);
      degree[t] += 1, degree[it->second] += 1;
    }
  for (Index t = 0; t < mesh.triangle_count(); ++t)
    entries.emplace_back(static_cast<int>(t), static_cast<int>(t), degree[t]);
  SparseMatrix L(mesh.triangle_count(), mesh.triangle_count());
  L.setFromTriplets(entries.begin(), entries.end());
  return L;
}

namespace {

/// Q⁻¹Jᵀ (#F by M) for a prior other than the identity (for Q = I it is Jᵀ, never formed).
Matrix prior_inverse_times_jt(const Matrix& J, const Mesh& mesh, Prior prior, double noser_exponent) {
  switch (prior) {
    case Prior::identity: return J.transpose();
    case Prior::noser: {
      // diag(JᵀJ)^p; columns that see nothing (all zero) get the mean so Q stays invertible.
      Vector q = J.colwise().squaredNorm().transpose().array().pow(noser_exponent);
      const double mean = q.mean();
      for (Index k = 0; k < q.size(); ++k)
        if (!(q[k] > 0)) q[k] = mean;
      return q.cwiseInverse().asDiagonal() * J.transpose();
    }
    case Prior::laplacian: {
      const SparseMatrix L = element_laplacian(mesh);
      SparseMatrix Q = SparseMatrix(L.transpose() * L);
      // LᵀL annihilates constants; a small ridge (1e-3 of its mean diagonal) makes Q definite
      // without changing what it penalises.
      const double ridge = 1e-3 * Q.diagonal().mean();
      for (Index k = 0; k < Q.rows(); ++k) Q.coeffRef(k, k) += ridge;
      SparseCholesky cholesky;
      cholesky.factorize(Q);
      return cholesky.solve(J.transpose());
    }
  }
  throw std::logic_error("unknown prior");
}

void check_lambda2(double lambda2) {
  if (!(lambda2 > 0) || !std::isfinite(lambda2))
    throw InvalidInput("lambda2 must be positive, got " + std::to_string(lambda2));
}

}  // namespace

Matrix build_reconstruction_operator(const Matrix& J, const Mesh& mesh, const OperatorOptions& options) {
  options.validate();
  const OperatorFamily family(J, mesh, options.prior, options.noser_exponent);
  return family.operator_for(family.lambda2_for(options));
}

CompactOperator build_compact_operator(Matrix J, const Mesh& mesh, const OperatorOptions& options) {
  options.validate();
  const OperatorFamily family(std::move(J), mesh, options.prior, options.noser_exponent);
  return family.compact_operator_for(family.lambda2_for(options), options.rank_cutoff);
}

double OperatorFamily::lambda2_for(const OperatorOptions& options) const {
  if (options.lambda2 == 0) return automatic_lambda2(sigma_, options.relative_lambda2);
  check_lambda2(options.lambda2);
  return options.lambda2;
}

OperatorFamily::OperatorFamily(Matrix J, const Mesh& mesh, Prior prior, double noser_exponent) : prior_(prior) {
  Matrix H;  // J Q⁻¹ Jᵀ, M × M, symmetric positive semi-definite; its lower triangle is what counts
  if (prior == Prior::identity) {
    H = Matrix::Zero(J.rows(), J.rows());
    H.selfadjointView<Eigen::Lower>().rankUpdate(J);  // half the work of J Jᵀ (BLAS syrk)
    J_ = std::move(J);
  } else {
    QiJt_ = prior_inverse_times_jt(J, mesh, prior, noser_exponent);
    H = J * QiJt_;
    H = 0.5 * (H + H.transpose()).eval();
  }
  SymmetricEigen eigen = symmetric_eigen(std::move(H));
  U_ = std::move(eigen.vectors);
  sigma_ = eigen.values.cwiseMax(0.0);  // round-off can make the smallest slightly negative
  if (prior != Prior::identity) {
    const Matrix basis = QiJt_ * U_;
    basis_gram_ = basis.transpose() * basis;
  }
}

Matrix OperatorFamily::prior_inverse_jt_times(const Matrix& X) const {
  return prior_ == Prior::identity ? Matrix(J_.transpose() * X) : Matrix(QiJt_ * X);
}

Eigen::MatrixXf OperatorFamily::prior_inverse_jt_times_in_float(const Matrix& X) const {
  // Row blocks of a few MiB in double, each rounded into the float result: no #F × k double
  // matrix is held (at 24k triangles its first touch alone took ~0.1 s; large_matrix.hpp).
  const Index rows = prior_ == Prior::identity ? J_.cols() : QiJt_.rows();
  constexpr Index block_rows = 2048;
  auto result = large_matrix<Eigen::MatrixXf>(rows, X.cols());
  Matrix block(std::min(block_rows, rows), X.cols());
  for (Index start = 0; start < rows; start += block_rows) {
    const Index n = std::min(block_rows, rows - start);
    if (prior_ == Prior::identity) block.topRows(n).noalias() = J_.middleCols(start, n).transpose() * X;
    else block.topRows(n).noalias() = QiJt_.middleRows(start, n) * X;
    result.middleRows(start, n) = block.topRows(n).cast<float>();
  }
  return result;
}

Matrix OperatorFamily::operator_for(double lambda2) const {
  check_lambda2(lambda2);
  const Vector filter = (sigma_.array() + lambda2).inverse();
  return prior_inverse_jt_times(U_ * filter.asDiagonal() * U_.transpose());
}

CompactOperator OperatorFamily::compact_operator_for(double lambda2, double relative_cutoff) const {
  check_lambda2(lambda2);
  if (!(relative_cutoff >= 0 && relative_cutoff < 1))
    throw InvalidInput("the operator's rank cutoff must be in [0, 1), got " + std::to_string(relative_cutoff));
  // R = W Uᵀ with W = Q⁻¹JᵀU·diag(f), f = 1/(σ + λ²), and U orthogonal, so R's singular values
  // and left vectors are W's. W = P S Vᵀ from W's Gram diag(f)·G·diag(f) = V S² Vᵀ; then
  // R ≈ (W V_k)(U V_k)ᵀ. For Q = I the Gram is diag(σ f²): V only sorts.
  const Vector f = (sigma_.array() + lambda2).inverse();
  const Index M = sigma_.size();
  Vector s2;
  Matrix V;
  if (prior_ == Prior::identity) {
    s2 = sigma_.cwiseProduct(f).cwiseProduct(f);
    V = Matrix::Identity(M, M);
  } else {
    SymmetricEigen eigen = symmetric_eigen(f.asDiagonal() * basis_gram_ * f.asDiagonal());
    s2 = std::move(eigen.values);
    V = std::move(eigen.vectors);
  }
  std::vector<Index> order(static_cast<std::size_t>(M));
  std::iota(order.begin(), order.end(), Index{0});
  std::sort(order.begin(), order.end(), [&](Index a, Index b) { return s2[a] > s2[b]; });
  const double s1 = M > 0 ? std::sqrt(std::max(0.0, s2[order[0]])) : 0.0;
  Index k = 0;
  while (k < M && std::sqrt(std::max(0.0, s2[order[static_cast<std::size_t>(k)]])) > relative_cutoff * s1) ++k;
  Matrix V_k(M, k);
  for (Index j = 0; j < k; ++j) V_k.col(j) = V.col(order[static_cast<std::size_t>(j)]);
  const double bound = k < M && s1 > 0 ? std::sqrt(std::max(0.0, s2[order[static_cast<std::size_t>(k)]])) / s1 : 0.0;
  const Matrix right = (U_ * V_k).transpose();
  const Matrix precision = U_ * f.asDiagonal() * U_.transpose();  // (J Q⁻¹ Jᵀ + λ² I)⁻¹
  return CompactOperator(prior_inverse_jt_times_in_float(U_ * f.asDiagonal() * V_k), right.cast<float>(), bound, s1,
                         lambda2, precision.cast<float>());
}

void OperatorOptions::validate() const {
  option_check::zero_or_positive("OperatorOptions", "lambda2", lambda2, "chosen from the spectrum");
  option_check::positive("OperatorOptions", "relative_lambda2", relative_lambda2);
  option_check::non_negative("OperatorOptions", "noser_exponent", noser_exponent);
  option_check::within("OperatorOptions", "rank_cutoff", rank_cutoff, 0, 1);
}
}  // namespace emit
