#include "emit/fem/sparse_cholesky.hpp"

#include <Eigen/OrderingMethods>
#include <Eigen/SparseCholesky>

#include "emit/errors.hpp"

namespace emit {

struct SparseCholesky::Impl {
  Eigen::SimplicialLDLT<SparseMatrix, Eigen::Lower, Eigen::AMDOrdering<int>> ldlt;
  bool analyzed = false, factorized = false;
};

SparseCholesky::SparseCholesky() : impl_(std::make_unique<Impl>()) {}
SparseCholesky::~SparseCholesky() = default;
SparseCholesky::SparseCholesky(SparseCholesky&&) noexcept = default;
SparseCholesky& SparseCholesky::operator=(SparseCholesky&&) noexcept = default;

void SparseCholesky::analyze(const SparseMatrix& pattern) {
  impl_->ldlt.analyzePattern(pattern);
  impl_->analyzed = true;
}

void SparseCholesky::factorize(const SparseMatrix& matrix) {
  if (!impl_->analyzed) analyze(matrix);
  impl_->ldlt.factorize(matrix);
  // LDLᵀ succeeds on indefinite matrices too; positive definiteness is a positive D.
  if (impl_->ldlt.info() != Eigen::Success || !(impl_->ldlt.vectorD().minCoeff() > 0))
    throw SolverError("sparse Cholesky: the matrix is not positive definite (is an electrode disconnected?)");
  impl_->factorized = true;
}

Matrix SparseCholesky::solve(const Matrix& rhs) const {
  if (!impl_->factorized) throw std::logic_error("SparseCholesky::solve before factorize");
  return impl_->ldlt.solve(rhs);
}

}  // namespace emit
