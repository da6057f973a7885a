#pragma once
/// \file sparse_cholesky.hpp
/// Sparse Cholesky (LDLᵀ with AMD fill-reducing ordering) with the symbolic analysis done once
/// per sparsity pattern and the numeric factorisation redone per matrix: the forward model's
/// matrix keeps its pattern from press to press.
///
/// Why Eigen's simplicial LDLᵀ and not CHOLMOD's supernodal LLᵀ: on these 2D meshes, with
/// Debian's reference BLAS, it measured 2–3× faster a frame (3.2 vs 9.6 ms at 6.8k triangles,
/// 172 vs 313 ms at 95k; bench/forward_bench), and its L, D and permutation are plain Eigen
/// objects, which selected inversion needs.
#include <memory>
#include <vector>

#include "emit/core/types.hpp"

namespace emit {

class SparseCholesky {
 public:
  SparseCholesky();
  ~SparseCholesky();
  SparseCholesky(SparseCholesky&&) noexcept;
  SparseCholesky& operator=(SparseCholesky&&) noexcept;
  SparseCholesky(const SparseCholesky&) = delete;  // move-only: it owns its factor
  SparseCholesky& operator=(const SparseCholesky&) = delete;

  /// Symbolic analysis of a symmetric matrix's pattern (only its lower triangle is read).
  void analyze(const SparseMatrix& pattern);
  /// Numeric factorisation; the pattern must be the analysed one.
  /// \throw SolverError if the matrix is not positive definite.
  void factorize(const SparseMatrix& matrix);
  /// Solve A X = B for the factorised A.
  Matrix solve(const Matrix& rhs) const;

  /// Selected inversion: the entries of A⁻¹ on the pattern of the factor (which holds the
  /// pattern of A), by the Takahashi recurrence on LDLᵀ, at about the cost of the factorisation.
  /// Returned lower triangle (row ≥ column) in A's own ordering; A⁻¹(i, j) for an (i, j) coupled
  /// in A is `Z.coeff(max(i, j), min(i, j))`.
  SparseMatrix selected_inverse() const;

  /// A⁻¹ on the rows and columns `index` (m indices of A's own ordering): a dense m × m block.
  /// L⁻¹Pe_a is nonzero only on the path from a to the root of the elimination tree, so the block
  /// costs m such sparse forward solves and one product over the union of their paths
  /// (A⁻¹(a, b) = yₐᵀD⁻¹y_b), not m full solves of n each.
  Matrix inverse_block(const std::vector<int>& index) const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace emit
