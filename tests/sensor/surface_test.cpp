// The sheet as a surface (sensor/surface.hpp): a spherical cap's points, normals and area against
// the sphere's closed forms; a flat sheet is the plane z = 0.
#include "emit/sensor/surface.hpp"

#include <cmath>
#include <numbers>

#include <gtest/gtest.h>

namespace emit {
namespace {

Shape cap(double sphere_radius_mm, double base_radius_mm) {
  Shape s;
  s.kind = ShapeKind::spherical_cap;
  s.sphere_radius_mm = sphere_radius_mm, s.radius_mm = base_radius_mm;
  return s;
}

// R = 25, a = 20: the sphere's centre 15 mm below the rim's plane. The apex at z = 10 facing +z;
// the rim's point (20, 0) at z = 0 facing (20, 0, 15)/25; (12, 9) at √(625 − 225) − 15 = 5.
TEST(Surface, SphericalCapPointsNormalsAndArea) {
  const Shape s = cap(25, 20);
  EXPECT_TRUE(is_curved(s));
  EXPECT_NEAR((surface_point_mm(s, {0, 0}) - Vector3(0, 0, 10)).norm(), 0, 1e-12);
  EXPECT_NEAR((surface_point_mm(s, {12, 9}) - Vector3(12, 9, 5)).norm(), 0, 1e-12);
  EXPECT_NEAR(surface_point_mm(s, {20, 0}).z(), 0, 1e-12);
  EXPECT_NEAR((surface_normal(s, {0, 0}) - Vector3::UnitZ()).norm(), 0, 1e-12);
  EXPECT_NEAR((surface_normal(s, {20, 0}) - Vector3(0.8, 0, 0.6)).norm(), 0, 1e-12);
  EXPECT_NEAR((surface_normal(s, {12, 9}) - Vector3(12, 9, 20) / 25).norm(), 0, 1e-12);
  EXPECT_NEAR(surface_area_mm2(s), 2 * std::numbers::pi * 25 * 10, 1e-9);        // 2πR·h, h = 10
  EXPECT_NEAR(surface_area_mm2(cap(20, 20)), 2 * std::numbers::pi * 400, 1e-9);  // a hemisphere
}

TEST(Surface, FlatSheetIsThePlane) {
  Shape s;
  s.kind = ShapeKind::rectangle, s.width_mm = 60, s.height_mm = 30;
  EXPECT_FALSE(is_curved(s));
  EXPECT_EQ(surface_point_mm(s, {12, 9}), Vector3(12, 9, 0));
  EXPECT_EQ(surface_normal(s, {12, 9}), Vector3::UnitZ());
  EXPECT_EQ(surface_area_mm2(s), 1800.0);
}

}  // namespace
}  // namespace emit
