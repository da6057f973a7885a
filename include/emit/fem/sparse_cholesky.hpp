#pragma once
/// \file sparse_cholesky.hpp
/// Sparse Cholesky factorisation (CHOLMOD, supernodal, AMD/METIS ordering) with the symbolic
/// analysis done once per sparsity pattern and the numeric factorisation redone per matrix: the
/// forward model's matrix keeps its pattern from press to press.
#include <memory>

#include "emit/types.hpp"

namespace emit {

class SparseCholesky {
 public:
  SparseCholesky();
  ~SparseCholesky();
  SparseCholesky(SparseCholesky&&) noexcept;
  SparseCholesky& operator=(SparseCholesky&&) noexcept;

  /// Symbolic analysis of a symmetric matrix's pattern (only its lower triangle is read).
  void analyze(const SparseMatrix& pattern);
  /// Numeric factorisation; the pattern must be the analysed one.
  /// \throw SolverError if the matrix is not positive definite.
  void factorize(const SparseMatrix& matrix);
  /// Solve A X = B for the factorised A.
  Matrix solve(const Matrix& rhs) const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace emit
