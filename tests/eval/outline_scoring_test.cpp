// Pressed regions scored against outlines (eval/outline_scoring.hpp), on analytic cases: a
// structured mesh of 0.5 mm squares, outlines along its grid lines (each triangle wholly in or
// out, so coverage is exact), and a disc whose covered area is π r² to the sampling's bound.
#include "emit/eval/outline_scoring.hpp"

#include <cmath>
#include <numbers>

#include <gtest/gtest.h>

#include "emit/core/errors.hpp"
#include "emit/sensor/press_outline.hpp"
#include "test_support.hpp"

namespace emit {
namespace {

Vector areas_of(const Mesh& mesh) {
  Vector areas(mesh.triangle_count());
  for (Index k = 0; k < mesh.triangle_count(); ++k) areas[k] = mesh.triangle_area_mm2(k);
  return areas;
}

// A 20 × 20 mm mesh of 0.5 mm squares.
Mesh grid() { return test::strip_mesh(20, 20, 40, 40); }

// A region against itself is 1; a bar against the same bar moved by half its length: |A∩B| is
// half of each, Dice 2·(A/2)/(2A) = 0.5; disjoint, 0. Exact: every triangle is wholly in or out.
TEST(OutlineScoring, DiceOfGridAlignedBars) {
  const Mesh mesh = grid();
  const Vector areas = areas_of(mesh);
  const Vector a = outline_coverage(mesh, {bar_press({10, 7.5}, 10, 5, 0, 1)});
  const Vector b = outline_coverage(mesh, {bar_press({15, 7.5}, 10, 5, 0, 1)});
  const Vector c = outline_coverage(mesh, {bar_press({10, 15}, 10, 5, 0, 1)});
  EXPECT_DOUBLE_EQ(areas.dot(a), 50);
  EXPECT_DOUBLE_EQ(area_dice(areas, a, a), 1);
  EXPECT_DOUBLE_EQ(area_dice(areas, a, b), 0.5);
  EXPECT_DOUBLE_EQ(area_dice(areas, a, c), 0);
  EXPECT_DOUBLE_EQ(area_dice(areas, Vector::Zero(areas.size()), Vector::Zero(areas.size())), 1);
}

// A disc's coverage sums to π r² within the pieces its rim crosses: each piece is counted wholly
// in or out by its centroid, so only those err, and they lie within a piece's diameter d (the
// triangles' 0.71 mm hypotenuse / 2^4) of the rim: at most the band's area 2d·2πr + πd².
TEST(OutlineScoring, DiscCoverageIsItsArea) {
  const Mesh mesh = grid();
  const double r = 6, d = std::sqrt(0.5) / 16;
  const Vector f = outline_coverage(mesh, {Press{10.2, 9.9, r, 1}}, 4);
  const double covered = areas_of(mesh).dot(f), bound = 2 * d * 2 * std::numbers::pi * r + std::numbers::pi * d * d;
  EXPECT_NEAR(covered, std::numbers::pi * r * r, bound);
  // Against a region of the triangles whose centroid is inside: they differ only in triangles
  // the rim crosses, within 0.71 mm of it, so Dice ≥ 1 − (that band's area)/(π r²).
  Vector region(mesh.triangle_count());
  for (Index k = 0; k < mesh.triangle_count(); ++k)
    region[k] = (mesh.triangle_centroid_mm(k).head<2>() - Vector2(10.2, 9.9)).norm() <= r ? 1 : 0;
  const double band = 2 * std::sqrt(0.5) * 2 * std::numbers::pi * r;
  EXPECT_GT(area_dice(areas_of(mesh), region, f), 1 - band / (std::numbers::pi * r * r));
}

TEST(OutlineScoring, AxesAndTheirDifferences) {
  EXPECT_NEAR(principal_angle_deg(press_second_moments_mm2(bar_press({0, 0}, 20, 4, 30, 1))), 30, 1e-9);
  EXPECT_NEAR(principal_angle_deg(press_second_moments_mm2(bar_press({0, 0}, 20, 4, 150, 1))), -30, 1e-9);
  EXPECT_DOUBLE_EQ(axis_difference_deg(170, 10), 20);
  EXPECT_DOUBLE_EQ(axis_difference_deg(-30, 150), 0);
  EXPECT_DOUBLE_EQ(axis_difference_deg(0, 90), 90);
}

// Two parallel bars 20 × 3 with centre lines 10 mm apart: the union's moments 20²/12 along and
// 3²/12 + 5² across, a ratio of 33.3/25.75 = 1.29, elongated along the bars (≥ 1.25); a single
// bar and an L are too, a disc and a ring are not.
TEST(OutlineScoring, TruthOfSeveralOutlines) {
  const OutlineTruth pair = outline_truth({bar_press({10, 5}, 20, 3, 0, 3), bar_press({10, 15}, 20, 3, 0, 5)});
  EXPECT_DOUBLE_EQ(pair.area_mm2, 120);
  EXPECT_DOUBLE_EQ(pair.force_N, 8);
  EXPECT_LT((pair.centroid_mm - Vector2(10, 10)).norm(), 1e-12);
  EXPECT_NEAR(pair.second_moments_mm2(0, 0), 400.0 / 12, 1e-9);
  EXPECT_NEAR(pair.second_moments_mm2(1, 1), 9.0 / 12 + 25, 1e-9);
  EXPECT_TRUE(pair.elongated);
  EXPECT_NEAR(pair.angle_deg, 0, 1e-9);
  EXPECT_TRUE(outline_truth({bar_press({0, 0}, 20, 6, 10, 1)}).elongated);
  EXPECT_FALSE(outline_truth({Press{0, 0, 12, 1}}).elongated);
  EXPECT_FALSE(outline_truth({ring_press({0, 0}, 6, 9, 1)}).elongated);
}

// A frame scored: the reconstructed region exactly the bar, its contact's force 10 % high.
TEST(OutlineScoring, FrameOfTheBarItself) {
  const Mesh mesh = grid();
  const Press bar = bar_press({10, 7.5}, 10, 5, 0, 4);
  const Vector coverage = outline_coverage(mesh, {bar});
  const Vector pressure = 0.1 * coverage;  // pressed where the bar is
  Contact contact;
  contact.force_N = 4.4;
  const OutlineScore s = score_outline_frame(mesh, coverage, pressure, {contact}, {bar});
  EXPECT_DOUBLE_EQ(s.dice, 1);
  EXPECT_DOUBLE_EQ(s.force_N, 4.4);
  EXPECT_DOUBLE_EQ(s.true_force_N, 4);
  EXPECT_NEAR(s.centroid_error_mm, 0, 1e-12);
  EXPECT_NEAR(s.orientation_error_deg, 0, 1e-9);
  EXPECT_DOUBLE_EQ(s.region_area_mm2, 50);
  EXPECT_EQ(s.regions, 1);
  EXPECT_EQ(s.presses, 1);
  // Nothing reconstructed: Dice 0, no centroid, the orientation the worst.
  const OutlineScore none = score_outline_frame(mesh, coverage, Vector::Zero(mesh.triangle_count()), {}, {bar});
  EXPECT_DOUBLE_EQ(none.dice, 0);
  EXPECT_TRUE(std::isnan(none.centroid_error_mm));
  EXPECT_DOUBLE_EQ(none.orientation_error_deg, 90);
  EXPECT_EQ(test::error_of([&] { score_outline_frame(mesh, coverage, Vector::Zero(3), {}, {bar}); }),
            "outline scoring: 3 pressures and 3200 coverages for 3200 triangles");
}

}  // namespace
}  // namespace emit
