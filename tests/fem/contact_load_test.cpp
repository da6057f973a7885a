// The contact term (fem/contact_load.hpp): the P1 mass matrix g·A/12·[2 1 1; 1 2 1; 1 1 2], whose
// entries sum to g·A, so a load's total conductance is ∫ g dA.
#include "emit/fem/contact_load.hpp"

#include <gtest/gtest.h>

#include "test_support.hpp"

namespace emit {
namespace {

TEST(ContactLoad, UniformMatrixIsTheP1MassMatrix) {
  const Eigen::Matrix3d m = uniform_contact_matrix(6.0, 2.0);  // g·A/12 = 1
  Eigen::Matrix3d expected;
  expected << 2, 1, 1, 1, 2, 1, 1, 1, 2;
  EXPECT_EQ(m, expected);
}

// On a 10 × 4 mm strip of 5 × 2 cells (20 triangles of 2 mm² each), g on every other triangle:
// 10 touched triangles, total conductance 10 · g · 2 mm² (a sum of 90 entries: a few ulps).
TEST(ContactLoad, SkipsUntouchedTrianglesAndSumsToTheIntegral) {
  const Mesh mesh = test::strip_mesh(10, 4, 5, 2);
  Vector g = Vector::Zero(mesh.triangle_count());
  for (Index t = 0; t < g.size(); t += 2) g[t] = 3e-6;
  const ContactLoad load = contact_load_from_elements(mesh, g);
  ASSERT_EQ(load.triangles.size(), 10u);
  EXPECT_FALSE(load.empty());
  EXPECT_EQ(load.triangles[1], 2);
  EXPECT_NEAR(load.total_conductance_S(), 10 * 3e-6 * 2.0, 1e-14 * 6e-5);
  EXPECT_TRUE(contact_load_from_elements(mesh, Vector::Zero(mesh.triangle_count())).empty());
}

}  // namespace
}  // namespace emit
