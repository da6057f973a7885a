// Contacts' outlines as polygons: a disc's and an ellipse's inscribed polygons against their
// closed forms, and a region's level line by marching triangles against the level set it
// approximates, the region's own triangles, the sheet's border, the vertex budget and no
// allocation per call.
#include "emit/frame/contact_outline.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <vector>

#include <gtest/gtest.h>
#include <Eigen/Eigenvalues>

#include "allocation_counter.hpp"
#include "emit/frame/contacts.hpp"
#include "test_support.hpp"

namespace emit {
namespace {

/// Mean and covariance of the uniform density over a counter-clockwise polygon, by its fan of
/// triangles from the first vertex (a triangle's: its vertices' mean; second moments
/// A/12 (Σ p_i p_iᵀ + (Σ p_i)(Σ p_i)ᵀ)), computed here apart from Outline::area_mm2.
struct Moments {
  double area = 0;
  Vector2 mean = Vector2::Zero();
  Eigen::Matrix2d covariance = Eigen::Matrix2d::Zero();
};
Moments moments(const Outline& outline) {
  Moments m;
  Eigen::Matrix2d second = Eigen::Matrix2d::Zero();
  const Vector2 o = outline.vertex_mm(0);
  for (int k = 1; k + 1 < outline.size; ++k) {
    const Vector2 p = outline.vertex_mm(k) - o, q = outline.vertex_mm(k + 1) - o;
    const double a = (p.x() * q.y() - p.y() * q.x()) / 2;
    const Vector2 sum = p + q;  // the third vertex is the origin
    m.area += a;
    m.mean += a * sum / 3;
    second += a / 12 * (p * p.transpose() + q * q.transpose() + sum * sum.transpose());
  }
  m.mean /= m.area;
  m.covariance = second / m.area - m.mean * m.mean.transpose();
  m.mean += o;
  return m;
}

double perimeter_mm(const Outline& outline) {
  double length = 0;
  for (int k = 0; k < outline.size; ++k)
    length += (outline.vertex_mm((k + 1) % outline.size) - outline.vertex_mm(k)).norm();
  return length;
}

// A disc's polygon: n vertices on the circle, its area πr² · n/(2π) sin(2π/n) (the inscribed
// regular polygon's); float vertices hold 7 digits.
TEST(ContactOutline, DiscPolygonHasTheInscribedPolygonsArea) {
  for (const int n : {8, ellipse_outline_vertices, Outline::capacity}) {
    Outline outline;
    ellipse_outline({12.5, -3.0}, 4.0, 4.0, 17.0, outline, n);
    ASSERT_EQ(outline.size, n);
    const double expected = std::numbers::pi * 16 * n / (2 * std::numbers::pi) * std::sin(2 * std::numbers::pi / n);
    EXPECT_NEAR(outline.area_mm2() / expected, 1, 1e-6) << n << " vertices";
    for (int k = 0; k < n; ++k) EXPECT_NEAR((outline.vertex_mm(k) - Vector2(12.5, -3.0)).norm(), 4.0, 1e-5);
  }
  // The default count's polygon is within 0.3 % of the circle's area.
  Outline outline;
  ellipse_outline({0, 0}, 4.0, 4.0, 0, outline);
  EXPECT_NEAR(outline.area_mm2() / (std::numbers::pi * 16), 1, 0.003);
  ellipse_outline({0, 0}, 0.0, 4.0, 0, outline);  // no size: no outline
  EXPECT_TRUE(outline.empty());
}

// An ellipse's polygon is the affine image of the regular polygon, whose variance along any axis
// is r² (2 + cos(2π/n))/12 (a fan of n triangles from the centre): along the ellipse's axes
// a² and b² times that, the major one at the ellipse's angle.
TEST(ContactOutline, EllipsePolygonsSecondMomentsMatchTheSemiAxes) {
  const double a = 12, b = 3, angle_deg = 30;
  Outline outline;
  ellipse_outline({20, 25}, a, b, angle_deg, outline);
  const Moments m = moments(outline);
  const int n = ellipse_outline_vertices;
  const double factor = (2 + std::cos(2 * std::numbers::pi / n)) / 12;
  EXPECT_NEAR(m.area / (std::numbers::pi * a * b * n / (2 * std::numbers::pi) * std::sin(2 * std::numbers::pi / n)), 1,
              1e-6);
  EXPECT_NEAR((m.mean - Vector2(20, 25)).norm(), 0, 1e-5);
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix2d> axes(m.covariance);
  EXPECT_NEAR(axes.eigenvalues()(1) / (a * a * factor), 1, 1e-5);
  EXPECT_NEAR(axes.eigenvalues()(0) / (b * b * factor), 1, 1e-5);
  const Vector2 major = axes.eigenvectors().col(1);
  EXPECT_NEAR(std::abs(major.dot(
                  Vector2(std::cos(angle_deg * std::numbers::pi / 180), std::sin(angle_deg * std::numbers::pi / 180)))),
              1, 1e-9);
  // And set_outline_ellipse reads the same semi-axes back from these moments, within the
  // polygon's factor (2 + cos(2π/n))/3 on the variances.
  Contact c;
  set_outline_ellipse(m.covariance, c);
  EXPECT_NEAR(c.semi_major_mm / (a * std::sqrt(factor * 4)), 1, 1e-5);
  EXPECT_NEAR(c.semi_minor_mm / (b * std::sqrt(factor * 4)), 1, 1e-5);
  EXPECT_NEAR(c.orientation_deg, angle_deg, 1e-4);
}

/// The 60 mm sheet in 50 × 50 square cells of 1.2 mm (two triangles each): a mesh edge is at most
/// h = 1.2·√2 mm.
constexpr double cell_mm = 1.2;
const double longest_edge_mm = cell_mm * std::sqrt(2.0);
Mesh square_sheet() { return test::strip_mesh(60.0, 60.0, 50, 50); }

/// An image whose level 0 is the circle of radius r about c: r² − |x − c|² at the centroids; the
/// region the elements at or above 0.
struct Paraboloid {
  Vector image;
  std::vector<int> region;
  double region_area_mm2 = 0;
  Paraboloid(const Mesh& mesh, const Vector2& c, double r) : image(mesh.triangle_count()) {
    for (Index t = 0; t < mesh.triangle_count(); ++t) {
      image[t] = r * r - (mesh.triangle_centroid_mm(t).head<2>() - c).squaredNorm();
      if (image[t] >= 0) {
        region.push_back(static_cast<int>(t));
        region_area_mm2 += mesh.triangle_area_mm2(t);
      }
    }
  }
};

// The level line of a field whose level set is a circle, r² − |x − c|² sampled at the centroids:
// averaging to a node adds the mean squared distance of its elements' centroids, under (2h/3)²,
// which moves the line by that over the gradient 2r (under 0.11 mm for r ≥ 6 mm on this mesh);
// linear interpolation along an edge errs by h²/8 over 2r (0.03 mm); the simplification's chords
// of a circle of ≥ 64 sides fall short by r(1 − cos(π/64)) (0.01 mm at 6 mm, more where it keeps
// fewer points on a stretch): every vertex within h/4 of the circle, and so its area within
// 2πr·h/4 of πr²; within the band, 2πr·h, of the region's triangles' area (which the centroids'
// sampling puts off the circle by up to a triangle); counter-clockwise; and a circle of 20 mm,
// ~200 crossings, comes out at the vertex budget.
TEST(ContactOutline, RegionsLevelLineFollowsTheLevelSet) {
  const Mesh mesh = square_sheet();
  RegionOutliner outliner(mesh);
  for (const double r : {6.0, 20.0}) {
    const Vector2 centre(31.3, 28.9);
    const Paraboloid field(mesh, centre, r);
    Outline outline;
    outliner.outline(field.image, 0.0, field.region, outline);
    ASSERT_GE(outline.size, 3);
    EXPECT_LE(outline.size, Outline::capacity);
    if (r == 20.0) {
      EXPECT_EQ(outline.size, Outline::capacity);
    }
    double farthest_mm = 0;
    for (int k = 0; k < outline.size; ++k)
      farthest_mm = std::max(farthest_mm, std::abs((outline.vertex_mm(k) - centre).norm() - r));
    const double band_mm2 = 2 * std::numbers::pi * r * longest_edge_mm;
    const double quarter_edge_mm = longest_edge_mm / 4;
    std::printf(
        "r %.0f mm: %d vertices, farthest %.3f mm from the circle, area %.1f mm² (circle %.1f, region "
        "%.1f)\n",
        r, outline.size, farthest_mm, outline.area_mm2(), std::numbers::pi * r * r, field.region_area_mm2);
    EXPECT_LT(farthest_mm, quarter_edge_mm);
    EXPECT_GT(outline.area_mm2(), 0);  // counter-clockwise
    EXPECT_NEAR(outline.area_mm2(), std::numbers::pi * r * r, 2 * std::numbers::pi * r * quarter_edge_mm);
    EXPECT_NEAR(outline.area_mm2(), field.region_area_mm2, band_mm2);
    // Before simplification the line lies in the band of triangles at the region's boundary
    // nodes; the simplification's dropped triangles add a little.
    EXPECT_NEAR(outline.area_mm2(), field.region_area_mm2, outliner.band_area_mm2(field.region));
  }
}

// A region reaching the sheet's border is closed along it: a disc centred on the edge x = 0 gives
// the half disc, with vertices on the border.
TEST(ContactOutline, RegionAtTheBorderIsClosedAlongIt) {
  const Mesh mesh = square_sheet();
  RegionOutliner outliner(mesh);
  const double r = 10;
  const Paraboloid field(mesh, {0.0, 30.0}, r);
  Outline outline;
  outliner.outline(field.image, 0.0, field.region, outline);
  ASSERT_GE(outline.size, 3);
  int on_border = 0;
  for (int k = 0; k < outline.size; ++k) {
    EXPECT_GE(outline.vertex_mm(k).x(), -1e-5);
    on_border += std::abs(outline.vertex_mm(k).x()) < 1e-5;
  }
  EXPECT_GE(on_border, 2);
  EXPECT_NEAR(outline.area_mm2(), std::numbers::pi * r * r / 2, (std::numbers::pi * r + 2 * r) * longest_edge_mm);
}

// Without a level, the region's indicator's half level: around the selected triangles, the
// area within the boundary band of the selection's; two regions touching at a vertex only stay
// apart (each outline within its own region's reach).
TEST(ContactOutline, IndicatorOutlineFollowsTheSelection) {
  const Mesh mesh = square_sheet();
  ContactFinder finder(mesh);
  std::vector<std::uint8_t> selected(static_cast<std::size_t>(mesh.triangle_count()), 0);
  Vector pressure = Vector::Zero(mesh.triangle_count());
  for (Index t = 0; t < mesh.triangle_count(); ++t) {
    const Vector2 c = mesh.triangle_centroid_mm(t).head<2>();
    if (std::abs(c.x() - 20) < 12 && std::abs(c.y() - 30) < 3) {  // a bar 24 × 6 mm
      selected[static_cast<std::size_t>(t)] = 1;
      pressure[t] = 0.01;
    }
  }
  const auto& contacts = finder.find(selected, pressure, Vector::Ones(mesh.triangle_count()));
  ASSERT_EQ(contacts.size(), 1u);
  const Outline& outline = contacts[0].outline;
  ASSERT_GE(outline.size, 4);
  const double perimeter = perimeter_mm(outline);
  std::printf("bar 24 x 6 mm: outline %.1f mm² (region %.1f), %d vertices\n", outline.area_mm2(), contacts[0].area_mm2,
              outline.size);
  EXPECT_NEAR(outline.area_mm2(), contacts[0].area_mm2, perimeter * longest_edge_mm);
  // Along the bar: its second moments' axis.
  const Moments m = moments(outline);
  EXPECT_GT(m.covariance(0, 0), 9 * m.covariance(1, 1));
}

// Per call, nothing allocated (the finder's and the outliner's buffers are sized at construction).
TEST(ContactOutline, OutliningAllocatesNothing) {
  const Mesh mesh = square_sheet();
  ContactFinder finder(mesh);
  const Paraboloid big(mesh, {30, 30}, 25);
  std::vector<std::uint8_t> selected(static_cast<std::size_t>(mesh.triangle_count()), 0);
  for (int t : big.region) selected[static_cast<std::size_t>(t)] = 1;
  const Vector pressure = Vector::Constant(mesh.triangle_count(), 0.01);
  const test::AllocationCounter counter;
  const auto& contacts = finder.find(selected, pressure, big.image, 0.0, nullptr, 0.0);
  EXPECT_EQ(counter.count(), 0);
  ASSERT_EQ(contacts.size(), 1u);
  EXPECT_EQ(contacts[0].outline.size, Outline::capacity);
}

// On the dome the outline is in the chart, (x, y) seen from +z: a level circle there comes out as
// on a flat sheet, within the mesh's longest edge.
TEST(ContactOutline, DomeOutlineIsInTheChart) {
  const Mesh& mesh = test::dome_mesh();
  RegionOutliner outliner(mesh, test::dome_sensor().shape);
  double longest = 0;
  for (Index t = 0; t < mesh.triangle_count(); ++t)
    for (int k = 0; k < 3; ++k)
      longest = std::max(longest,
                         (mesh.nodes_mm.row(mesh.triangles(t, k)) - mesh.nodes_mm.row(mesh.triangles(t, (k + 1) % 3)))
                             .norm());
  const Vector2 centre(3, -2);
  const double r = 6;
  const Paraboloid field(mesh, centre, r);
  Outline outline;
  outliner.outline(field.image, 0.0, field.region, outline);
  ASSERT_GE(outline.size, 3);
  EXPECT_GT(outline.area_mm2(), 0);
  for (int k = 0; k < outline.size; ++k) EXPECT_NEAR((outline.vertex_mm(k) - centre).norm(), r, longest);
}

}  // namespace
}  // namespace emit
