#include "emit/fem/sparse_cholesky.hpp"

#include <Eigen/CholmodSupport>

#include "emit/errors.hpp"

namespace emit {

struct SparseCholesky::Impl {
  Eigen::CholmodSupernodalLLT<SparseMatrix, Eigen::Lower> llt;
  bool analyzed = false, factorized = false;
};

SparseCholesky::SparseCholesky() : impl_(std::make_unique<Impl>()) {}
SparseCholesky::~SparseCholesky() = default;
SparseCholesky::SparseCholesky(SparseCholesky&&) noexcept = default;
SparseCholesky& SparseCholesky::operator=(SparseCholesky&&) noexcept = default;

void SparseCholesky::analyze(const SparseMatrix& pattern) {
  impl_->llt.analyzePattern(pattern);
  impl_->analyzed = true;
}

void SparseCholesky::factorize(const SparseMatrix& matrix) {
  if (!impl_->analyzed) analyze(matrix);
  impl_->llt.factorize(matrix);
  if (impl_->llt.info() != Eigen::Success)
    throw SolverError("sparse Cholesky: the matrix is not positive definite (is an electrode disconnected?)");
  impl_->factorized = true;
}

Matrix SparseCholesky::solve(const Matrix& rhs) const {
  if (!impl_->factorized) throw std::logic_error("SparseCholesky::solve before factorize");
  return impl_->llt.solve(rhs);
}

}  // namespace emit
