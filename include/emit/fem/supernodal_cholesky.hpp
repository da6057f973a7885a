#pragma once
/// \file supernodal_cholesky.hpp
/// CHOLMOD's supernodal Cholesky (P A Pᵀ = L Lᵀ, L stored as dense column blocks) and selected
/// inversion on it: the entries of A⁻¹ on A's own pattern, which is what the Jacobian needs of
/// the grounded Green's function (docs/physics.md, "The Jacobian").
///
/// Why a second Cholesky beside SparseCholesky: selected inversion runs the Takahashi recurrence
/// over every pair of rows in each column of L. On Eigen's simplicial factor each pair is a
/// sparse look-up (a binary search); on the supernodal factor a supernode's pairs are one dense
/// block, gathered once and swept by BLAS (dtrsm, dsymm, dgemm). Measured on the default sensor
/// (one thread, best of 3): selected inversion at 23k triangles 0.94 s simplicial, 0.023 s
/// supernodal (factorisation with analysis 0.038 s); at 93k, 12.9 s against 0.10–0.16 s. The
/// forward model keeps SparseCholesky (its header says why).
#include <memory>

#include "emit/core/types.hpp"

namespace emit {

class SupernodalCholesky {
 public:
  SupernodalCholesky();
  ~SupernodalCholesky();
  SupernodalCholesky(SupernodalCholesky&&) noexcept;
  SupernodalCholesky& operator=(SupernodalCholesky&&) noexcept;
  SupernodalCholesky(const SupernodalCholesky&) = delete;  // move-only: it owns its factor
  SupernodalCholesky& operator=(const SupernodalCholesky&) = delete;

  /// Analyse and factorise a symmetric positive definite matrix (only its lower triangle is
  /// read). \throw SolverError if it is not positive definite.
  void factorize(const SparseMatrix& matrix);
  /// Solve A X = B. \pre factorize succeeded.
  Matrix solve(const Matrix& rhs) const;
  /// Selected inversion: A⁻¹ on the lower triangle of A's own pattern (row ≥ column), in A's
  /// ordering, as a matrix with exactly that pattern. A⁻¹(i, j) for (i, j) coupled in A is
  /// `Z.coeff(max(i, j), min(i, j))`. Costs a few times the factorisation.
  /// \pre factorize succeeded.
  SparseMatrix selected_inverse() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace emit
