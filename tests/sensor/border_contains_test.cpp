// Whether a point is on the sheet (Border::contains) along the lines where the border's pieces
// meet. A circle is four quarter arcs whose ends, cos and sin of kπ/2, land a few 1e-15 mm from
// where the next arc starts; the polyline the even-odd rule walks was open there, so a point on
// y = 0 between the two ends crossed no piece on that side and fell "off the sheet": the dome's
// apex, where `emit live --source sim` took its finger after 3 s (issue 32).
#include <cmath>
#include <numbers>

#include <gtest/gtest.h>

#include "emit/sensor/border.hpp"

namespace emit {
namespace {

// The apex as the twin's press script computed it, (1.3e-15, -2.0e-15), and other points a
// rounding away from the lines y = 0 and x = 0 through the centre: all inside, by the 20 mm radius
// less a few 1e-15 mm, so the answer cannot depend on rounding.
TEST(BorderContains, PointsOnTheLinesWhereArcsMeetAreInside) {
  for (const Vector2& centre : {Vector2(0, 0), Vector2(30, 30), Vector2(-7.5, 12.25)}) {
    const Border circle = Border::circle(centre, 20);
    for (const Vector2& offset : {Vector2(1.3e-15, -2.0e-15), Vector2(0, 0), Vector2(0, -1e-15), Vector2(0, 1e-15),
                                  Vector2(-10, -4.9e-15), Vector2(10, -4.9e-15), Vector2(19.9, 2e-15),
                                  Vector2(-19.9, -2e-15), Vector2(-3e-15, 15), Vector2(2e-15, -15)})
      EXPECT_TRUE(circle.contains(centre + offset))
          << "centre (" << centre.transpose() << ") + (" << offset.transpose() << ")";
    // And outside stays outside on those lines: 20.01 mm out along each axis.
    for (const Vector2& offset : {Vector2(20.01, -2e-15), Vector2(-20.01, 2e-15), Vector2(1e-15, 20.01)})
      EXPECT_FALSE(circle.contains(centre + offset)) << "(" << offset.transpose() << ")";
  }
}

// The same on a ring of points all around at radius 19.9 mm and 20.1 mm: every angle, the
// pieces' joints among them (k·90°), is inside and outside as it should be.
TEST(BorderContains, AllAroundACircle) {
  const Border circle = Border::circle({0, 0}, 20);
  for (int k = 0; k < 720; ++k) {
    const double angle = std::numbers::pi * k / 360;
    const Vector2 direction(std::cos(angle), std::sin(angle));
    EXPECT_TRUE(circle.contains(19.9 * direction)) << k;
    EXPECT_TRUE(circle.contains(1e-14 * direction)) << k;
    EXPECT_FALSE(circle.contains(20.1 * direction)) << k;
  }
}

}  // namespace
}  // namespace emit
