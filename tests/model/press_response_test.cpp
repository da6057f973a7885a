// The press response's basis and a frame's relative change (model/press_response.hpp).
#include "emit/model/press_response.hpp"

#include <cmath>

#include <gtest/gtest.h>

namespace emit {
namespace {

TEST(PressResponse, BasisIsTheMonomialsDegreeByDegree) {
  PressResponse r;
  r.degree = 3;
  r.center_mm = {10, 20};
  r.scale_mm = 2;
  ASSERT_EQ(response_basis_size(3), 10);
  Vector b(10);
  r.basis_at({16, 22}, b);  // u = 3, v = 1
  const double u = 3, v = 1;
  const Vector expected =
      (Vector(10) << 1, v, u, v * v, u * v, u * u, v * v * v, u * v * v, u * u * v, u * u * u).finished();
  EXPECT_EQ((b - expected).norm(), 0);
  r.basis_at({10, 16}, b);  // u = 0, v = −2
  EXPECT_EQ(b(6), -8);
  EXPECT_EQ(b(9), 0);
}

TEST(PressResponse, RegionIsTheConvexHull) {
  // A square's corners, a point inside and one on an edge: the hull is the corners,
  // counter-clockwise from the lowest-leftmost.
  const std::vector<Vector2> hull = convex_hull({{1, 1}, {0, 0}, {2, 0}, {2, 2}, {0, 2}, {1, 0}, {0, 0}});
  ASSERT_EQ(hull.size(), 4u);
  EXPECT_EQ(hull[0], Vector2(0, 0));
  EXPECT_EQ(hull[1], Vector2(2, 0));
  EXPECT_EQ(hull[2], Vector2(2, 2));
  EXPECT_EQ(hull[3], Vector2(0, 2));
  PressResponse r;
  r.region_mm = hull;
  EXPECT_TRUE(r.in_region({1, 1}));
  EXPECT_TRUE(r.in_region({2, 1}));  // on the border
  EXPECT_FALSE(r.in_region({2.001, 1}));
  EXPECT_FALSE(r.in_region({-0.001, 1}));
  EXPECT_EQ(convex_hull({{0, 0}, {1, 1}, {2, 2}}).size(), 2u);  // collinear: its ends
}

TEST(PressResponse, RelativeChangeIsTheNormalisedLogRatio) {
  const Vector reference = (Vector(3) << 100, 200, 50).finished();
  const Vector frame = (Vector(3) << 101, 198, 50).finished();
  Vector d(3);
  const double size = relative_change(frame, reference, d);
  const Vector log_ratio = (Vector(3) << std::log(1.01), std::log(0.99), 0).finished();
  EXPECT_NEAR(size, log_ratio.norm(), 1e-15);
  EXPECT_NEAR((d - log_ratio / log_ratio.norm()).norm(), 0, 1e-15);
  EXPECT_EQ(relative_change(reference, reference, d), 0);  // no change to normalise
  // A reading that cannot be used is masked (NaN), the rest normalised; a dropped channel reads 0.
  Vector bad = frame;
  bad(1) = 0;
  EXPECT_NEAR(relative_change(bad, reference, d), std::log(1.01), 1e-15);
  EXPECT_EQ(d(0), 1);
  EXPECT_TRUE(std::isnan(d(1)));
  EXPECT_EQ(d(2), 0);
  bad(1) = std::nan("");
  EXPECT_TRUE(relative_change(bad, reference, d) > 0 && std::isnan(d(1)));
  ReadingScreen screen;
  screen.rail = 150;  // 198 and 200 are clipped
  screen.dropped = {0, 1, 0};
  EXPECT_NEAR(relative_change(frame, reference, d, screen), std::log(1.01), 1e-15);
  EXPECT_EQ(d(1), 0);
  screen.dropped = {0, 0, 0};
  EXPECT_TRUE(relative_change(frame, reference, d, screen) > 0 && std::isnan(d(1)));
  bad.setConstant(-1);
  EXPECT_EQ(relative_change(bad, reference, d), 0);  // nothing to use
}

}  // namespace
}  // namespace emit
