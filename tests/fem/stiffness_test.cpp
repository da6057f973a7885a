// P1 stiffness: operator identities, linear precision, and validity in 3D.
#include "emit/fem/stiffness.hpp"

#include <gtest/gtest.h>
#include <Eigen/Dense>

#include "test_support.hpp"
#include "tolerances.hpp"

namespace emit {
namespace {

using test::operator_identity;

Mesh small_mesh() { return test::strip_mesh(6.0, 4.0, 6, 4); }

TEST(Stiffness, AnnihilatesConstants) {
  const SparseMatrix K = assemble_stiffness(small_mesh(), 2e-4);
  const Vector K1 = K * Vector::Ones(K.cols());
  // Relative to the largest entry: each row sums O(10) entries of that size.
  EXPECT_LE(K1.cwiseAbs().maxCoeff(), operator_identity * K.coeffs().cwiseAbs().maxCoeff());
}

TEST(Stiffness, IsSymmetric) {
  const SparseMatrix K = assemble_stiffness(small_mesh(), 1.0);
  const Matrix dense(K);
  EXPECT_LE((dense - dense.transpose()).cwiseAbs().maxCoeff(), operator_identity);
}

TEST(Stiffness, PositiveDefiniteOnceGrounded) {
  const SparseMatrix K = assemble_stiffness(small_mesh(), 1.0);
  const Matrix grounded = Matrix(K).bottomRightCorner(K.rows() - 1, K.cols() - 1);
  const Eigen::SelfAdjointEigenSolver<Matrix> eig(grounded);
  EXPECT_GT(eig.eigenvalues().minCoeff(), 1e-6);  // strictly positive, far above round-off
  // and the ungrounded K has exactly one zero eigenvalue (the constant)
  const Eigen::SelfAdjointEigenSolver<Matrix> full(Matrix{K});
  EXPECT_LE(std::abs(full.eigenvalues()[0]), 1e-12);
  EXPECT_GT(full.eigenvalues()[1], 1e-6);
}

// Linear precision (patch test): for u linear, (K u)_i = 0 at every interior node, because
// ∫ ∇φ_i · c dA = 0 for a constant gradient c when φ_i vanishes on the patch's border.
TEST(Stiffness, LinearPrecisionOnInteriorNodes) {
  Mesh mesh = small_mesh();
  // Perturb interior nodes so the patch is irregular.
  for (Index v = 0; v < mesh.node_count(); ++v) {
    const double x = mesh.nodes_mm(v, 0), y = mesh.nodes_mm(v, 1);
    if (x > 0 && x < 6 && y > 0 && y < 4)
      mesh.nodes_mm.row(v) += Vector3(0.2 * std::sin(3 * v), 0.2 * std::cos(5 * v), 0);
  }
  const SparseMatrix K = assemble_stiffness(mesh, 1.0);
  const Vector u = 0.7 * mesh.nodes_mm.col(0) - 1.3 * mesh.nodes_mm.col(1) + Vector::Constant(mesh.node_count(), 2.0);
  const Vector Ku = K * u;
  for (Index v = 0; v < mesh.node_count(); ++v) {
    const double x = mesh.nodes_mm(v, 0), y = mesh.nodes_mm(v, 1);
    if (x > 1e-9 && x < 6 - 1e-9 && y > 1e-9 && y < 4 - 1e-9) {
      EXPECT_NEAR(Ku[v], 0.0, 1e-13) << "node " << v;
    }
  }
}

// A sheet rotated into 3D has the same stiffness: the edge-vector form does not assume a plane.
TEST(Stiffness, InvariantUnderRotationInto3D) {
  const Mesh flat = small_mesh();
  Mesh tilted = flat;
  const Eigen::Matrix3d R = (Eigen::AngleAxisd(0.7, Vector3(1, 2, 3).normalized())).toRotationMatrix();
  for (Index v = 0; v < tilted.node_count(); ++v)
    tilted.nodes_mm.row(v) = (R * Vector3(flat.nodes_mm.row(v))).transpose();
  const Matrix difference = Matrix(assemble_stiffness(flat, 1.0)) - Matrix(assemble_stiffness(tilted, 1.0));
  EXPECT_LE(difference.cwiseAbs().maxCoeff(), operator_identity);
}

// Local stiffness of the right triangle (0,0), (1,0), (0,1) is known in closed form.
TEST(Stiffness, ReferenceTriangle) {
  const Eigen::Matrix3d k = local_stiffness(Vector3(0, 0, 0), Vector3(1, 0, 0), Vector3(0, 1, 0), 1.0);
  Eigen::Matrix3d expected;
  expected << 1.0, -0.5, -0.5, -0.5, 0.5, 0.0, -0.5, 0.0, 0.5;
  EXPECT_LE((k - expected).cwiseAbs().maxCoeff(), operator_identity);
}

}  // namespace
}  // namespace emit
