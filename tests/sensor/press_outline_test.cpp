// Flat punches of any outline (sensor/press_outline.hpp): their area, centroid and second moments
// against the closed forms, where they press, and how they are parsed and refused.
#include "emit/sensor/press_outline.hpp"

#include <cmath>
#include <numbers>

#include <gtest/gtest.h>

#include "emit/core/errors.hpp"
#include "emit/sensor/sensor_json.hpp"
#include "test_support.hpp"

namespace emit {
namespace {

// Every figure is a polygon's shoelace sum: exact to round-off (1e-12 relative).
constexpr double round_off = 1e-12;

// A bar L × W turned by θ: area L W, centroid its centre, moments R diag(L²/12, W²/12) Rᵀ.
TEST(PressOutline, BarHasTheRectanglesMoments) {
  const double length = 30, width = 3, angle = 37;
  const Press bar = bar_press({21, 33}, length, width, angle, 9);
  EXPECT_NEAR(press_area_mm2(bar), length * width, round_off * length * width);
  EXPECT_NEAR((press_centroid_mm(bar) - Vector2(21, 33)).norm(), 0, round_off * 30);
  const double a = angle * std::numbers::pi / 180;
  Eigen::Matrix2d rotation;
  rotation << std::cos(a), -std::sin(a), std::sin(a), std::cos(a);
  const Eigen::Matrix2d expected =
      rotation * Eigen::Vector2d(length * length / 12, width * width / 12).asDiagonal() * rotation.transpose();
  EXPECT_LT((press_second_moments_mm2(bar) - expected).norm(), round_off * expected.norm());
  EXPECT_DOUBLE_EQ(bar.pressure_N_per_mm2(), 9 / (length * width));
  // The reach is the farthest corner: half the diagonal.
  EXPECT_NEAR(bar.radius_mm, std::hypot(length, width) / 2, round_off * 30);
  EXPECT_TRUE(press_covers(bar, Vector2(21, 33) + 14 * Vector2(std::cos(a), std::sin(a))));
  EXPECT_FALSE(press_covers(bar, Vector2(21, 33) + 2 * Vector2(-std::sin(a), std::cos(a))));
}

// A ring of n-gons: (n/2) sin(2π/n)(R² − r²), centred, with a hole that is not pressed.
TEST(PressOutline, RingIsTheAnnulusOfItsPolygons) {
  const Press ring = ring_press({30, 30}, 6, 9, 8);
  const int n = outline_curve_vertices;
  const double area = n / 2.0 * std::sin(2 * std::numbers::pi / n) * (81 - 36);
  EXPECT_NEAR(press_area_mm2(ring), area, round_off * area);
  // 2π²/(3n²) short of the circles' annulus: the polygon's, not the circle's, is what is pressed.
  EXPECT_NEAR(press_area_mm2(ring) / (std::numbers::pi * 45), 1 - 2 * std::pow(std::numbers::pi / n, 2) / 3, 1e-6);
  EXPECT_NEAR((press_centroid_mm(ring) - Vector2(30, 30)).norm(), 0, 1e-12);
  EXPECT_FALSE(press_covers(ring, {30, 30}));
  EXPECT_TRUE(press_covers(ring, {37.5, 30}));
  EXPECT_FALSE(press_covers(ring, {40, 30}));
  EXPECT_DOUBLE_EQ(ring.radius_mm, 9);
}

// An L of two 20 × 4 bars: area 2·80 − 16 = 144, centroid (80·(10, 2) + 64·(2, 12))/144.
TEST(PressOutline, LShapedPolygonHasItsCentroid) {
  const Press l = polygon_press({10, 10}, {{{-10, -10}, {10, -10}, {10, -6}, {-6, -6}, {-6, 10}, {-10, 10}}}, 12);
  EXPECT_NEAR(press_area_mm2(l), 144, round_off * 144);
  const double c = (80 * 10 + 64 * 2) / 144.0;
  EXPECT_LT((press_centroid_mm(l) - Vector2(c, c)).norm(), round_off * 20);
  EXPECT_TRUE(press_covers(l, {1, 15}));
  EXPECT_FALSE(press_covers(l, {10, 10}));
  // Either orientation of the vertices gives the same outline.
  const Press reversed =
      polygon_press({10, 10}, {{{-10, 10}, {-6, 10}, {-6, -6}, {10, -6}, {10, -10}, {-10, -10}}}, 12);
  EXPECT_NEAR(press_area_mm2(reversed), 144, round_off * 144);
}

// A disc's figures are the disc's: π r², its centre, r²/4 · I.
TEST(PressOutline, DiscKeepsItsClosedForms) {
  const Press disc{10, 20, 4, 5};
  EXPECT_DOUBLE_EQ(press_area_mm2(disc), std::numbers::pi * 16);
  EXPECT_EQ(press_centroid_mm(disc), Vector2(10, 20));
  EXPECT_EQ(press_second_moments_mm2(disc), Eigen::Matrix2d(4 * Eigen::Matrix2d::Identity()));
  EXPECT_TRUE(press_covers(disc, {14, 20}));
  EXPECT_FALSE(press_covers(disc, {14.01, 20}));
}

TEST(PressOutline, ParsesEachKind) {
  const Press bar = parse_press("bar:30,31,20,6,45,8");
  EXPECT_EQ(bar.x_mm, 30.0);
  EXPECT_EQ(bar.y_mm, 31.0);
  EXPECT_NEAR(press_area_mm2(bar), 120, round_off * 120);
  EXPECT_EQ(bar.force_N, 8.0);
  EXPECT_NEAR(press_area_mm2(parse_press("ellipse:30,30,12,6,10,8")),
              outline_curve_vertices / 2.0 * std::sin(2 * std::numbers::pi / outline_curve_vertices) * 72, 1e-9);
  EXPECT_NEAR(press_area_mm2(parse_press("ring:30,30,6,9,8")), press_area_mm2(ring_press({30, 30}, 6, 9, 8)), 1e-12);
  const Press triangle = parse_press("polygon:30,30,5, 0,0, 4,0, 0,3");
  EXPECT_NEAR(press_area_mm2(triangle), 6, round_off * 6);
  EXPECT_EQ(triangle.force_N, 5.0);
}

TEST(PressOutline, RefusesBadOutlinesByName) {
  EXPECT_EQ(test::error_of([] { parse_press("star:1,2,3"); }),
            "press \"star:1,2,3\": \"star\" is not an outline (bar, ellipse, ring, polygon)");
  EXPECT_EQ(test::error_of([] { parse_press("bar:1,2,3,4,5"); }),
            "press \"bar:1,2,3,4,5\": expected 6 values x_mm,y_mm,length_mm,width_mm,angle_deg,force_N, got 5");
  EXPECT_EQ(test::error_of([] { parse_press("bar:1,2,x,4,5,6"); }),
            "press \"bar:1,2,x,4,5,6\": \"x\" is not a number (expected "
            "x_mm,y_mm,length_mm,width_mm,angle_deg,force_N)");
  EXPECT_EQ(test::error_of([] { parse_press("bar:1,2,0,4,5,6"); }), "bar length must be a positive length, got 0");
  EXPECT_EQ(test::error_of([] { parse_press("ring:1,2,5,4,6"); }),
            "ring: inner radius 5 mm must be below the outer 4 mm");
  EXPECT_EQ(test::error_of([] { parse_press("polygon:1,2,3,0,0,1,1"); }),
            "press \"polygon:1,2,3,0,0,1,1\": expected x_mm,y_mm,force_N and 3 or more vertices u,v "
            "(x_mm,y_mm,force_N,u1,v1,u2,v2,u3,v3[,...]), got 7 values");
  EXPECT_EQ(test::error_of([] { parse_press("polygon:1,2,3,0,0,1,1,2,2"); }), "polygon: the outline encloses no area");
}

// Outlines are pressed on flat sheets only, flat.
TEST(PressOutline, ValidatedAgainstTheSheet) {
  const Sensor flat = default_sensor();
  Press bar = bar_press({30, 30}, 20, 6, 0, 8);
  EXPECT_EQ(test::error_of([&] { validate_press(flat, bar, "press 0"); }), "no error");
  bar.profile = PressProfile::spherical;
  EXPECT_EQ(test::error_of([&] { validate_press(flat, bar, "press 0"); }), "press 0: an outline press must be flat");
  const Sensor& dome = test::dome_sensor();
  const Press on_dome = bar_press({0, 0}, 10, 4, 0, 8);
  EXPECT_EQ(test::error_of([&] { validate_press(dome, on_dome, "press 1"); }),
            "press 1: an outline press needs a flat sheet");
}

}  // namespace
}  // namespace emit
