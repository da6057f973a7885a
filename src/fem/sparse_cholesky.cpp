#include "emit/fem/sparse_cholesky.hpp"

#include <Eigen/OrderingMethods>
#include <Eigen/SparseCholesky>

#include <algorithm>
#include <vector>

#include "emit/core/errors.hpp"

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

SparseMatrix SparseCholesky::selected_inverse() const {
  if (!impl_->factorized) throw std::logic_error("SparseCholesky::selected_inverse before factorize");
  // P A Pᵀ = L D Lᵀ, L unit lower triangular stored strictly below the diagonal, columns sorted.
  const SparseMatrix& L = impl_->ldlt.matrixL().nestedExpression();
  const Vector& D = impl_->ldlt.vectorD();
  const int n = static_cast<int>(L.cols());
  const int* start = L.outerIndexPtr();
  const int* row = L.innerIndexPtr();
  const double* l_value = L.valuePtr();
  std::vector<double> z_value(static_cast<std::size_t>(L.nonZeros()));  // Z on L's pattern
  Vector z_diagonal(n);
  // Z(a, b) for a > b in L's pattern: binary search in column b.
  auto z_at = [&](int a, int b) {
    if (a == b) return z_diagonal[a];
    if (a < b) std::swap(a, b);
    const int* first = row + start[b];
    const int* last = row + start[b + 1];
    const int* it = std::lower_bound(first, last, a);
    return z_value[static_cast<std::size_t>(it - row)];
  };
  // Takahashi: Z = D⁻¹L⁻¹ + (I − Lᵀ) Z, swept from the last column back. The rows of column i
  // form a clique of the filled graph, so every Z(j, k) needed is already on the pattern.
  for (int i = n - 1; i >= 0; --i) {
    for (int p = start[i]; p < start[i + 1]; ++p) {
      double sum = 0;
      for (int q = start[i]; q < start[i + 1]; ++q) sum += l_value[q] * z_at(row[p], row[q]);
      z_value[static_cast<std::size_t>(p)] = -sum;
    }
    double diagonal = 1.0 / D[i];
    for (int p = start[i]; p < start[i + 1]; ++p) diagonal -= l_value[p] * z_value[static_cast<std::size_t>(p)];
    z_diagonal[i] = diagonal;
  }
  // Back to A's ordering: permuted index r is original index P⁻¹(r).
  const auto& perm = impl_->ldlt.permutationPinv().indices();
  std::vector<Eigen::Triplet<double, int>> entries;
  entries.reserve(z_value.size() + static_cast<std::size_t>(n));
  auto add = [&](int r, int c, double v) {
    const int a = perm[r], b = perm[c];
    entries.emplace_back(std::max(a, b), std::min(a, b), v);
  };
  for (int c = 0; c < n; ++c) {
    add(c, c, z_diagonal[c]);
    for (int p = start[c]; p < start[c + 1]; ++p) add(row[p], c, z_value[static_cast<std::size_t>(p)]);
  }
  SparseMatrix Z(n, n);
  Z.setFromTriplets(entries.begin(), entries.end());
  return Z;
}

}  // namespace emit
