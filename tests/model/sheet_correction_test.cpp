// The sheet's smooth correction (model/sheet_correction.hpp) against its formula at hand-picked
// points: σ/σ_nominal = exp(θ·b(u, v)), (u, v) the point scaled to [−1, 1] over the box.
#include "emit/model/sheet_correction.hpp"

#include <cmath>

#include <gtest/gtest.h>

#include "test_support.hpp"

namespace emit {
namespace {

TEST(SheetCorrection, IdentityOverTheMeshIsItsBoundingBoxAndFactorOne) {
  const Mesh mesh = test::strip_mesh(30, 10, 6, 2);
  const SheetCorrection c = SheetCorrection::identity_over(mesh);
  EXPECT_EQ(c.lower_mm, Vector2(0, 0));
  EXPECT_EQ(c.upper_mm, Vector2(30, 10));
  const auto [low, high] = c.factor_range(mesh);
  EXPECT_EQ(low, 1.0);
  EXPECT_EQ(high, 1.0);
  // Uncorrected, each triangle's conductance is 1/Rs.
  EXPECT_EQ(c.element_conductance_S(mesh, 500).cwiseAbs().maxCoeff(), 1.0 / 500);
  EXPECT_EQ(c.element_conductance_S(mesh, 500).minCoeff(), 1.0 / 500);
}

// The box's corners and centre map to (±1, ±1) and (0, 0); all values are exact in binary.
TEST(SheetCorrection, BasisAndFactorFollowTheFormula) {
  SheetCorrection c;
  c.lower_mm = {0, 0};
  c.upper_mm = {40, 20};
  const auto corner = c.basis({40, 0});  // u = 1, v = −1
  EXPECT_EQ(corner, (std::vector<double>{1, -1, 1, -1, 1}));
  const auto quarter = c.basis({30, 15});  // u = 0.5, v = 0.5
  EXPECT_EQ(quarter, (std::vector<double>{0.5, 0.5, 0.25, 0.25, 0.25}));
  c.log_conductance = {0.2, -0.1, 0.05, 0.3, 0};
  EXPECT_EQ(c.factor({20, 10}), 1.0);  // the centre: every basis function is 0
  EXPECT_NEAR(c.factor({40, 0}), std::exp(0.2 + 0.1 + 0.05 - 0.3), 1e-15);
  // Cubic: the four third-order terms follow, u³, u²v, uv², v³.
  c.log_conductance = {0, 0, 0, 0, 0, 1, 2, 4, 8};
  EXPECT_EQ(c.basis({30, 15}), (std::vector<double>{0.5, 0.5, 0.25, 0.25, 0.25, 0.125, 0.125, 0.125, 0.125}));
  EXPECT_NEAR(c.factor({40, 0}), std::exp(1 - 2 + 4 - 8), 1e-15);
}

// θ = (ln 2, 0, …): the factor is 2^u. On a 6 × 2 strip over [0, 30] mm the centroids nearest the
// sides are 5/3 mm from them (a third of a 5 mm cell), at u = ±8/9: the range is 2^(∓8/9).
TEST(SheetCorrection, RangeAndConductanceFollowTheFactor) {
  const Mesh mesh = test::strip_mesh(30, 10, 6, 2);
  SheetCorrection c = SheetCorrection::identity_over(mesh);
  c.log_conductance[0] = std::log(2.0);
  const auto [low, high] = c.factor_range(mesh);
  EXPECT_NEAR(low, std::pow(2.0, -8.0 / 9), 1e-12);
  EXPECT_NEAR(high, std::pow(2.0, 8.0 / 9), 1e-12);
  const Vector g = c.element_conductance_S(mesh, 1000);
  for (Index t = 0; t < mesh.triangle_count(); ++t)
    EXPECT_NEAR(g[t], std::pow(2.0, mesh.triangle_centroid_mm(t).x() / 15 - 1) / 1000, 1e-15);
}

}  // namespace
}  // namespace emit
