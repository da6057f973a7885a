#include "emit/fem/sparse_cholesky.hpp"

#include <Eigen/OrderingMethods>
#include <Eigen/SparseCholesky>

#include <algorithm>
#include <cmath>
#include <stdexcept>
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

Matrix SparseCholesky::inverse_block(const std::vector<int>& index) const {
  if (!impl_->factorized) throw std::logic_error("SparseCholesky::inverse_block before factorize");
  const SparseMatrix& L = impl_->ldlt.matrixL().nestedExpression();  // strictly lower, unit diagonal
  const Vector& D = impl_->ldlt.vectorD();
  const auto& permuted = impl_->ldlt.permutationP().indices();  // A's index a is row permuted[a] of L
  const int n = static_cast<int>(L.cols());
  const int* start = L.outerIndexPtr();
  const int* row = L.innerIndexPtr();
  const double* l_value = L.valuePtr();
  // Forward solves L y = e_r along the elimination tree (a column's parent is its first row).
  std::vector<double> work(static_cast<std::size_t>(n), 0.0);
  std::vector<int> compact(static_cast<std::size_t>(n), -1), rows;  // union of the paths
  std::vector<std::vector<std::pair<int, double>>> y(index.size());
  for (std::size_t k = 0; k < index.size(); ++k) {
    if (index[k] < 0 || index[k] >= n) throw std::out_of_range("SparseCholesky::inverse_block: an index out of range");
    work[static_cast<std::size_t>(permuted[index[k]])] = 1.0;
    for (int j = permuted[index[k]]; j >= 0; j = start[j] < start[j + 1] ? row[start[j]] : -1) {
      const double v = work[static_cast<std::size_t>(j)];
      work[static_cast<std::size_t>(j)] = 0;
      for (int p = start[j]; p < start[j + 1]; ++p) work[static_cast<std::size_t>(row[p])] -= l_value[p] * v;
      y[k].emplace_back(j, v / std::sqrt(D[j]));  // D^{-1/2} y: the block is then a Gram matrix
      if (compact[static_cast<std::size_t>(j)] < 0) {
        compact[static_cast<std::size_t>(j)] = static_cast<int>(rows.size());
        rows.push_back(j);
      }
    }
  }
  Matrix Y = Matrix::Zero(static_cast<Index>(rows.size()), static_cast<Index>(index.size()));
  for (std::size_t k = 0; k < index.size(); ++k)
    for (const auto& [j, v] : y[k]) Y(compact[static_cast<std::size_t>(j)], static_cast<Index>(k)) = v;
  Matrix block(Y.cols(), Y.cols());
  block.noalias() = Y.transpose() * Y;
  return block;
}

}  // namespace emit
