// The sparse Cholesky wrapper: solves to round-off, reuses its analysis, refuses indefinite input.
#include "emit/fem/sparse_cholesky.hpp"

#include <gtest/gtest.h>

#include "emit/core/errors.hpp"
#include "emit/fem/stiffness.hpp"
#include "test_support.hpp"
#include "tolerances.hpp"

namespace emit {
namespace {

SparseMatrix grounded_stiffness(double conductance_S, double shift) {
  const SparseMatrix K = assemble_stiffness(test::strip_mesh(5, 5, 10, 10), conductance_S);
  SparseMatrix A = K.bottomRightCorner(K.rows() - 1, K.cols() - 1);
  for (Index i = 0; i < A.rows(); ++i) A.coeffRef(i, i) += shift;
  return A;
}

TEST(SparseCholesky, SolvesAndReusesTheAnalysisForNewValues) {
  SparseCholesky cholesky;
  const SparseMatrix A = grounded_stiffness(1.0, 0.0);
  cholesky.analyze(A);
  const Matrix B = Matrix::Random(A.rows(), 3);
  for (double shift : {0.0, 0.5}) {
    const SparseMatrix M = grounded_stiffness(1.0, shift);  // same pattern, other values
    cholesky.factorize(M);
    const Matrix X = cholesky.solve(B);
    // Backward error of a stable Cholesky solve: ‖M X − B‖ ≲ cond · eps ‖B‖; cond < 1e4 here.
    EXPECT_LE((M * X - B).norm(), test::solve_roundoff * B.norm()) << "shift " << shift;
  }
}

TEST(SparseCholesky, RefusesAnIndefiniteMatrix) {
  SparseCholesky cholesky;
  EXPECT_THROW(cholesky.factorize(grounded_stiffness(1.0, -10.0)), SolverError);
}

}  // namespace
}  // namespace emit

namespace emit {
namespace {

// Selected inversion against the dense inverse, on every entry of the factor's pattern. The
// recurrence is backward stable: agreement to cond(A)·eps relative to the largest entry.
TEST(SparseCholesky, SelectedInverseMatchesTheDenseInverse) {
  const SparseMatrix A = grounded_stiffness(1.0, 0.01);
  SparseCholesky cholesky;
  cholesky.factorize(A);
  const SparseMatrix Z = cholesky.selected_inverse();
  const Matrix inverse = Matrix(A).inverse();
  double worst = 0;
  int checked = 0;
  for (int c = 0; c < Z.outerSize(); ++c)
    for (SparseMatrix::InnerIterator it(Z, c); it; ++it) {
      EXPECT_GE(it.row(), it.col());
      worst = std::max(worst, std::abs(it.value() - inverse(it.row(), it.col())));
      ++checked;
    }
  EXPECT_LE(worst, test::solve_roundoff * inverse.cwiseAbs().maxCoeff());
  // every coupling of A is there
  for (int c = 0; c < A.outerSize(); ++c)
    for (SparseMatrix::InnerIterator it(A, c); it; ++it)
      if (it.row() >= it.col()) {
        EXPECT_NE(Z.coeff(it.row(), it.col()), 0.0) << it.row() << ", " << it.col();
      }
  EXPECT_GT(checked, A.nonZeros() / 2);
}

}  // namespace
}  // namespace emit

namespace emit {
namespace {

// A block of the inverse by forward solves along the elimination tree, against the dense
// inverse: the same backward-stable arithmetic as a solve, so agreement to cond(A)·eps of the
// largest entry. Indices scattered and unsorted, one repeated: the block follows the order given.
TEST(SparseCholesky, InverseBlockMatchesTheDenseInverse) {
  const SparseMatrix A = grounded_stiffness(1.0, 0.01);
  SparseCholesky cholesky;
  cholesky.factorize(A);
  const Matrix inverse = Matrix(A).inverse();
  const int n = static_cast<int>(A.rows());
  const std::vector<int> index{n - 1, 0, n / 2, 7, n / 3, 7, 1};
  const Matrix block = cholesky.inverse_block(index);
  ASSERT_EQ(block.rows(), static_cast<Index>(index.size()));
  double worst = 0;
  for (std::size_t a = 0; a < index.size(); ++a)
    for (std::size_t b = 0; b < index.size(); ++b)
      worst =
          std::max(worst, std::abs(block(static_cast<Index>(a), static_cast<Index>(b)) - inverse(index[a], index[b])));
  EXPECT_LE(worst, test::solve_roundoff * inverse.cwiseAbs().maxCoeff());
  EXPECT_THROW(cholesky.inverse_block({n}), std::out_of_range);
}

}  // namespace
}  // namespace emit
