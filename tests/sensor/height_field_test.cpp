// A file's surface charted by (x, y) (sensor/height_field.hpp): on a tilted plane, triangulated, the
// heights, normal, slopes and area are the plane's closed forms to rounding; its outline is the
// square it covers; surfaces that +z does not see once are refused.
#include "emit/sensor/height_field.hpp"

#include <cmath>

#include <gtest/gtest.h>

#include "emit/core/errors.hpp"

namespace emit {
namespace {

/// The plane z = 2 + 0.3x − 0.2y over [0, 10]², n × n squares each cut in two.
void tilted_plane(int n, HeightField::Nodes& nodes, HeightField::Triangles& triangles) {
  nodes.resize(Index{n + 1} * (n + 1), 3);
  for (int j = 0; j <= n; ++j)
    for (int i = 0; i <= n; ++i) {
      const double x = 10.0 * i / n, y = 10.0 * j / n;
      nodes.row(j * (n + 1) + i) << x, y, 2 + 0.3 * x - 0.2 * y;
    }
  triangles.resize(Index{2} * n * n, 3);
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      const int a = j * (n + 1) + i, b = a + 1, c = a + n + 1, d = c + 1;
      triangles.row(Index{2} * (j * n + i)) << a, b, d;
      triangles.row(Index{2} * (j * n + i) + 1) << a, c, d;  // clockwise: any orientation is taken
    }
}

TEST(HeightField, ATiltedPlaneIsItsClosedForm) {
  HeightField::Nodes nodes;
  HeightField::Triangles triangles;
  tilted_plane(7, nodes, triangles);
  const HeightField plane(nodes, triangles, "plane");
  const Vector3 n = Vector3(-0.3, 0.2, 1).normalized();
  for (const Vector2& c : {Vector2(0.1, 0.2), Vector2(3.3, 7.7), Vector2(9.99, 5), Vector2(10, 10)}) {
    EXPECT_NEAR((plane.point_mm(c) - Vector3(c.x(), c.y(), 2 + 0.3 * c.x() - 0.2 * c.y())).norm(), 0, 1e-12);
    EXPECT_NEAR((plane.normal(c) - n).norm(), 0, 1e-12);
    Eigen::Matrix<double, 3, 2> t;
    t << 1, 0, 0, 1, 0.3, -0.2;
    EXPECT_NEAR((plane.tangents(c) - t).norm(), 0, 1e-12);
  }
  // Beyond the border: (x, y) kept, at the nearest triangle's height there (its plane's, clamped).
  EXPECT_NEAR(plane.point_mm({10.5, 5}).z(), 2 + 0.3 * 10 - 0.2 * 5, 1e-12);
  EXPECT_NEAR(plane.area_mm2(), 100 * std::sqrt(1 + 0.09 + 0.04), 1e-9);
  EXPECT_TRUE(plane.is_curved());
  ASSERT_TRUE(plane.outline().has_value());
  EXPECT_NEAR(plane.outline()->length_mm(), 40, 1e-9);
  EXPECT_TRUE(plane.outline()->contains({5, 5}));
  EXPECT_NEAR(plane.outline()->distance_to_border_mm({5, 2}), 2, 1e-12);
}

TEST(HeightField, RefusesASurfaceSeenTwiceOrEdgeOn) {
  HeightField::Nodes nodes;
  HeightField::Triangles triangles;
  tilted_plane(4, nodes, triangles);
  // A second sheet 1 mm above, shifted half a square: +z sees (x, y) there twice.
  HeightField::Nodes two(2 * nodes.rows(), 3);
  two << nodes, nodes.rowwise() + Eigen::RowVector3d(1.25, 1.25, 1);
  HeightField::Triangles both(2 * triangles.rows(), 3);
  both << triangles, triangles.array() + static_cast<int>(nodes.rows());
  try {
    HeightField folded(two, both, "two.msh");
    FAIL() << "a folded surface was charted";
  } catch (const InvalidInput& e) {
    EXPECT_NE(std::string(e.what()).find("two.msh: the surface covers ("), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("twice seen from +z"), std::string::npos) << e.what();
  }
  HeightField::Nodes wall(3, 3);
  wall << 0, 0, 0, 1, 0, 0, 0.5, 0, 1;  // in the plane y = 0: edge-on from +z
  HeightField::Triangles one(1, 3);
  one << 0, 1, 2;
  EXPECT_THROW(HeightField(wall, one, "wall.stl"), InvalidInput);
  EXPECT_THROW(HeightField(wall, HeightField::Triangles(0, 3), "empty.msh"), InvalidInput);
}

}  // namespace
}  // namespace emit
