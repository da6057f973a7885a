#include "emit/reconstruct/reconstruction_operator.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <map>

#include <Eigen/Dense>

#include "emit/errors.hpp"
#include "emit/fem/sparse_cholesky.hpp"

namespace emit {

OperatorOptions method_options(const std::string& method) {
  OperatorOptions options;
  if (method == "paper") return options;
  if (method == "noser") {
    options.prior = Prior::noser;
    options.lambda2 = 1.5e3;
    return options;
  }
  if (method == "laplacian") {
    options.prior = Prior::laplacian;
    options.lambda2 = 6.0e5;
    return options;
  }
  throw InvalidInput("unknown method \"" + method + "\" (paper, noser, laplacian)");
}

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
  for (Index t = 0; t < mesh.triangle_count(); ++t) entries.emplace_back(static_cast<int>(t), static_cast<int>(t), degree[t]);
  SparseMatrix L(mesh.triangle_count(), mesh.triangle_count());
  L.setFromTriplets(entries.begin(), entries.end());
  return L;
}

namespace {

/// Q⁻¹Jᵀ (#F by M) for the chosen prior.
Matrix prior_inverse_times_jt(const Matrix& J, const Mesh& mesh, const OperatorOptions& options) {
  switch (options.prior) {
    case Prior::identity: return J.transpose();
    case Prior::noser: {
      // diag(JᵀJ)^p; columns that see nothing (all zero) get the mean so Q stays invertible.
      Vector q = J.colwise().squaredNorm().transpose().array().pow(options.noser_exponent);
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

}  // namespace

Matrix build_reconstruction_operator(const Matrix& J, const Mesh& mesh, const OperatorOptions& options) {
  return OperatorFamily(J, mesh, options.prior, options.noser_exponent).operator_for(options.lambda2);
}

OperatorFamily::OperatorFamily(const Matrix& J, const Mesh& mesh, Prior prior, double noser_exponent) {
  OperatorOptions options;
  options.prior = prior;
  options.noser_exponent = noser_exponent;
  const Matrix QiJt = prior_inverse_times_jt(J, mesh, options);  // #F × M
  const Matrix H = J * QiJt;                                     // M × M, symmetric positive semi-definite
  const Eigen::SelfAdjointEigenSolver<Matrix> eigen(0.5 * (H + H.transpose()));
  U_ = eigen.eigenvectors();
  sigma_ = eigen.eigenvalues().cwiseMax(0.0);  // round-off can make the smallest slightly negative
  basis_ = QiJt * U_;
}

Matrix OperatorFamily::operator_for(double lambda2) const {
  if (!(lambda2 > 0) || !std::isfinite(lambda2))
    throw InvalidInput("lambda2 must be positive, got " + std::to_string(lambda2));
  const Vector filter = (sigma_.array() + lambda2).inverse();
  return basis_ * filter.asDiagonal() * U_.transpose();
}

}  // namespace emit
