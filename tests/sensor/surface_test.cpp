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

Shape cylinder(double radius_mm, double length_mm, double angle_deg) {
  Shape s;
  s.kind = ShapeKind::cylinder;
  s.radius_mm = radius_mm, s.length_mm = length_mm, s.angle_deg = angle_deg;
  return s;
}

// A patch R = 20, L = 60, α = 90°: the chart is [0, 60] × [0, 10π]. Its middle (30, 5π) is the
// top (0, 0, 20); v = 0 is θ = −45°, the point (−30, −20/√2, 20/√2) at u = 0. The area is RαL.
TEST(Surface, CylinderPatchIsTheUnrolledRectangle) {
  const Shape s = cylinder(20, 60, 90);
  const double pi = std::numbers::pi;
  EXPECT_TRUE(is_curved(s));
  EXPECT_FALSE(is_sleeve(s));
  EXPECT_NEAR((surface_point_mm(s, {30, 5 * pi}) - Vector3(0, 0, 20)).norm(), 0, 1e-12);
  EXPECT_NEAR((surface_point_mm(s, {0, 0}) - Vector3(-30, -20 / std::sqrt(2.0), 20 / std::sqrt(2.0))).norm(), 0, 1e-12);
  EXPECT_NEAR((surface_normal(s, {0, 0}) - Vector3(0, -1, 1) / std::sqrt(2.0)).norm(), 0, 1e-12);
  EXPECT_NEAR(surface_area_mm2(s), 20 * pi / 2 * 60, 1e-9);
  // The inverse, and the tangents against central differences (the map is smooth: h² ≈ 1e-8).
  for (const Vector2& c : {Vector2(3, 1), Vector2(30, 5 * pi), Vector2(57, 30)}) {
    EXPECT_NEAR((surface_chart_mm(s, surface_point_mm(s, c)) - c).norm(), 0, 1e-12);
    const double h = 1e-4;
    for (int k = 0; k < 2; ++k) {
      const Vector2 step = h * Vector2::Unit(k);
      const Vector3 difference = (surface_point_mm(s, c + step) - surface_point_mm(s, c - step)) / (2 * h);
      EXPECT_NEAR((surface_tangents(s, c).col(k) - difference).norm(), 0, 1e-7);
    }
    // An isometry: orthonormal tangents, and the normal is their cross product (outward).
    const auto t = surface_tangents(s, c);
    EXPECT_NEAR((t.transpose() * t - Eigen::Matrix2d::Identity()).norm(), 0, 1e-12);
    EXPECT_NEAR((t.col(0).cross(t.col(1)) - surface_normal(s, c)).norm(), 0, 1e-12);
  }
  // A point off the sheet goes to the nearest one along the radius.
  EXPECT_NEAR((surface_chart_mm(s, Vector3(0, 0, 35)) - Vector2(30, 5 * pi)).norm(), 0, 1e-12);
}

// A sleeve's chart is periodic: v and v + 2πR are the same point, and the inverse gives v in [0, 2πR).
TEST(Surface, SleeveChartIsPeriodic) {
  const Shape s = cylinder(15, 60, 360);
  const double round = 2 * std::numbers::pi * 15;
  EXPECT_TRUE(is_sleeve(s));
  EXPECT_NEAR((surface_point_mm(s, {10, 1}) - surface_point_mm(s, {10, 1 + round})).norm(), 0, 1e-12);
  EXPECT_NEAR((wrapped_chart_mm(s, {10, -1}) - Vector2(10, round - 1)).norm(), 0, 1e-12);
  // v = 0 is θ = −180°: the bottom (0, 0, −15); the seam's other side maps back near 2πR.
  EXPECT_NEAR((surface_point_mm(s, {30, 0}) - Vector3(0, 0, -15)).norm(), 0, 1e-12);
  const Vector2 c = surface_chart_mm(s, surface_point_mm(s, {30, round - 0.5}));
  EXPECT_NEAR((c - Vector2(30, round - 0.5)).norm(), 0, 1e-12);
  EXPECT_NEAR(surface_area_mm2(s), round * 60, 1e-9);
}

// The margin presses keep: a patch's chart keeps its rectangle's distances, so a point 2 mm
// from a side is 2 mm in (and −1 mm outside); around a sleeve the seam is no border, only the
// rims are (the chart rectangle's lower side v = 0 is 2πR from nothing).
TEST(Surface, ChartDistanceToBorderIsTheRimsOnASleeve) {
  const Shape patch = cylinder(20, 60, 120), sleeve = cylinder(15, 60, 360);
  const Border patch_border = Border::rectangle(60, 20 * 2 * std::numbers::pi / 3);
  EXPECT_NEAR(chart_distance_to_border_mm(patch, patch_border, {30, 2}), 2, 1e-12);
  EXPECT_NEAR(chart_distance_to_border_mm(patch, patch_border, {30, -1}), -1, 1e-12);
  const Border sleeve_chart = Border::rectangle(60, 2 * std::numbers::pi * 15);
  EXPECT_NEAR(chart_distance_to_border_mm(sleeve, sleeve_chart, {7, 0.5}), 7, 1e-12);
  EXPECT_NEAR(chart_distance_to_border_mm(sleeve, sleeve_chart, {57, 50}), 3, 1e-12);
  EXPECT_NEAR(chart_distance_to_border_mm(sleeve, sleeve_chart, {61, 50}), -1, 1e-12);
}

// Seen from +z: the cap's point of chart (x, y), the cylinder's upper point z = √(R² − y²), the
// plane's z = 0; y beyond the cylinder's radius is taken at its side.
TEST(Surface, PointAboveIsTheUpperOne) {
  EXPECT_NEAR((surface_point_above_mm(cap(25, 20), {12, 9}) - Vector3(12, 9, 5)).norm(), 0, 1e-12);
  EXPECT_NEAR((surface_point_above_mm(cylinder(15, 60, 360), {-8, 9}) - Vector3(-8, 9, 12)).norm(), 0, 1e-12);
  EXPECT_NEAR((surface_point_above_mm(cylinder(15, 60, 360), {0, 20}) - Vector3(0, 15, 0)).norm(), 0, 1e-12);
  EXPECT_NEAR((surface_point_above_mm(Shape{}, {3, 4}) - Vector3(3, 4, 0)).norm(), 0, 1e-12);
}

}  // namespace
}  // namespace emit
