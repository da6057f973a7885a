// LAPACK's symmetric eigensolver through our wrapper: it must give back a matrix's known
// eigenpairs (to round-off: relative 1e-12 is ~1e4 ulps of the largest value for n = 60).
#include "emit/model/symmetric_eigen.hpp"

#include <gtest/gtest.h>
#include <Eigen/QR>

#include "emit/core/errors.hpp"

namespace emit {
namespace {

TEST(SymmetricEigen, RecoversKnownEigenpairsAscending) {
  const int n = 60;
  const Matrix Q = Eigen::HouseholderQR<Matrix>(Matrix::Random(n, n)).householderQ();
  const Vector values = Vector::LinSpaced(n, -3.0, 50.0);
  const Matrix A = Q * values.asDiagonal() * Q.transpose();
  const SymmetricEigen eigen = symmetric_eigen(A);
  EXPECT_LE((eigen.values - values).cwiseAbs().maxCoeff(), 1e-12 * 50.0);
  EXPECT_LE((eigen.vectors * eigen.values.asDiagonal() * eigen.vectors.transpose() - A).cwiseAbs().maxCoeff(),
            1e-12 * 50.0);
  EXPECT_LE((eigen.vectors.transpose() * eigen.vectors - Matrix::Identity(n, n)).cwiseAbs().maxCoeff(), 1e-12);
}

TEST(SymmetricEigen, ReadsTheLowerTriangleOnlyAndRefusesANonSquareMatrix) {
  Matrix A(2, 2);
  A << 2.0, 99.0, 1.0, 2.0;  // the upper 99 is ignored: eigenvalues of [[2, 1], [1, 2]] are 1 and 3
  const SymmetricEigen eigen = symmetric_eigen(A);
  EXPECT_NEAR(eigen.values[0], 1.0, 1e-14);
  EXPECT_NEAR(eigen.values[1], 3.0, 1e-14);
  EXPECT_THROW(symmetric_eigen(Matrix::Zero(2, 3)), InvalidInput);
}

}  // namespace
}  // namespace emit
