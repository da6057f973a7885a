// CHOLMOD's supernodal Cholesky and the block selected inversion on it: against the dense
// inverse, and against the simplicial recurrence (SparseCholesky) on a mesh large enough to have
// supernodes of many columns.
#include "emit/fem/supernodal_cholesky.hpp"

#include <gtest/gtest.h>

#include "emit/core/errors.hpp"
#include "emit/fem/sparse_cholesky.hpp"
#include "emit/fem/stiffness.hpp"
#include "test_support.hpp"
#include "tolerances.hpp"

namespace emit {
namespace {

/// Stiffness of a strip_mesh(…, nx, ny) grounded at its first node, shifted on the diagonal.
SparseMatrix grounded_stiffness(int nx, int ny, double shift) {
  const SparseMatrix K = assemble_stiffness(test::strip_mesh(5, 5, nx, ny), 1.0);
  SparseMatrix A = K.bottomRightCorner(K.rows() - 1, K.cols() - 1);
  for (Index i = 0; i < A.rows(); ++i) A.coeffRef(i, i) += shift;
  return A;
}

TEST(SupernodalCholesky, Solves) {
  const SparseMatrix A = grounded_stiffness(10, 10, 0.0);
  SupernodalCholesky cholesky;
  cholesky.factorize(A);
  const Matrix B = Matrix::Random(A.rows(), 3);
  // Backward error of a stable Cholesky solve: ‖A X − B‖ ≲ cond · eps ‖B‖; cond < 1e4 here.
  EXPECT_LE((A * cholesky.solve(B) - B).norm(), test::solve_roundoff * B.norm());
}

TEST(SupernodalCholesky, RefusesAnIndefiniteMatrix) {
  SupernodalCholesky cholesky;
  EXPECT_THROW(cholesky.factorize(grounded_stiffness(10, 10, -10.0)), SolverError);
}

// Exactly A's lower pattern comes back, each entry the dense inverse's to cond(A)·eps relative
// to the largest (the block recurrence is backward stable, as the simplicial one).
TEST(SupernodalCholesky, SelectedInverseMatchesTheDenseInverseOnAsPattern) {
  const SparseMatrix A = grounded_stiffness(10, 10, 0.01);
  SupernodalCholesky cholesky;
  cholesky.factorize(A);
  const SparseMatrix Z = cholesky.selected_inverse();
  const SparseMatrix lower = A.triangularView<Eigen::Lower>();
  ASSERT_EQ(Z.nonZeros(), lower.nonZeros());
  const Matrix inverse = Matrix(A).inverse();
  double worst = 0;
  for (int c = 0; c < Z.outerSize(); ++c)
    for (SparseMatrix::InnerIterator it(Z, c), a(lower, c); it; ++it, ++a) {
      ASSERT_EQ(it.row(), a.row());
      worst = std::max(worst, std::abs(it.value() - inverse(it.row(), it.col())));
    }
  EXPECT_LE(worst, test::solve_roundoff * inverse.cwiseAbs().maxCoeff());
}

// ~5k unknowns: supernodes of tens of columns, gathers across many ancestors. The two
// recurrences round differently; both are within cond(A)·eps of A⁻¹.
TEST(SupernodalCholesky, SelectedInverseMatchesTheSimplicialRecurrence) {
  const SparseMatrix A = grounded_stiffness(70, 70, 0.0);
  SupernodalCholesky supernodal;
  supernodal.factorize(A);
  SparseCholesky simplicial;
  simplicial.factorize(A);
  const SparseMatrix Z = supernodal.selected_inverse(), reference = simplicial.selected_inverse();
  double worst = 0, largest = 0;
  for (int c = 0; c < Z.outerSize(); ++c)
    for (SparseMatrix::InnerIterator it(Z, c); it; ++it) {
      worst = std::max(worst, std::abs(it.value() - reference.coeff(it.row(), c)));
      largest = std::max(largest, std::abs(it.value()));
    }
  EXPECT_LE(worst, test::solve_roundoff * largest);
}

}  // namespace
}  // namespace emit
