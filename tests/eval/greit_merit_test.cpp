// GREIT's figures of merit (eval/greit_merit.hpp) on images whose figures are known analytically:
// discs, a shifted disc, a disc with a negative ring, an ellipse, drawn on a structured mesh of
// the 60 mm sheet. The mesh's elements (h = 0.5 mm squares, halved) draw a disc as a staircase;
// each tolerance is that staircase's, stated where it is used.
#include "emit/eval/greit_merit.hpp"

#include <algorithm>
#include <cmath>
#include <functional>
#include <numbers>

#include <gtest/gtest.h>

#include "emit/core/errors.hpp"

namespace emit {
namespace {

constexpr double side_mm = 60, h_mm = 0.5;

/// [0, 60]² in h squares, each cut into two triangles (counter-clockwise).
const Mesh& square_mesh() {
  static const Mesh mesh = [] {
    Mesh m;
    const auto n = static_cast<Index>(side_mm / h_mm);
    m.nodes_mm.resize((n + 1) * (n + 1), 3);
    for (Index j = 0; j <= n; ++j)
      for (Index i = 0; i <= n; ++i)
        m.nodes_mm.row(j * (n + 1) + i) << static_cast<double>(i) * h_mm, static_cast<double>(j) * h_mm, 0;
    m.triangles.resize(2 * n * n, 3);
    for (Index j = 0; j < n; ++j)
      for (Index i = 0; i < n; ++i) {
        const auto a = static_cast<int>(j * (n + 1) + i), b = a + 1, c = a + static_cast<int>(n) + 2,
                   d = a + static_cast<int>(n) + 1;
        m.triangles.row(2 * (j * n + i)) << a, b, c;
        m.triangles.row(2 * (j * n + i) + 1) << a, c, d;
      }
    return m;
  }();
  return mesh;
}

/// An image whose value at each element is f(its centroid).
Vector drawn(const std::function<double(const Vector2&)>& f) {
  const Mesh& mesh = square_mesh();
  Vector image(mesh.triangle_count());
  for (Index t = 0; t < mesh.triangle_count(); ++t) image[t] = f(mesh.triangle_centroid_mm(t).head<2>());
  return image;
}

Vector disc_image(const Vector2& centre, double radius_mm) {
  return drawn([=](const Vector2& p) { return (p - centre).norm() <= radius_mm ? 1.0 : 0.0; });
}

// A disc's staircase departs from its rim by under one element (h) across: its area is within
// 2πr·h/2 of πr² (so RES within h/r of RES's relative value), and the part of it outside the circle
// of equal area is at most that band, SD ≤ h/r. Its centre of gravity is the disc's by symmetry of
// the grid about a node, to rounding.
TEST(GreitMerit, UniformDiscOnTheTarget) {
  const Vector2 target(20, 30);
  const double r = 6;
  const GreitMerit m = greit_figures_of_merit(square_mesh(), disc_image(target, r), target, std::numbers::pi * r * r);
  EXPECT_NEAR(m.position_error_mm, 0, 1e-6);
  EXPECT_LT(m.shape_deformation, h_mm / r);
  EXPECT_EQ(m.ringing, 0);  // nothing of the opposite sign
  const double res = std::sqrt(std::numbers::pi * r * r / (side_mm * side_mm));
  EXPECT_NEAR(m.resolution, res, res * h_mm / r);
  EXPECT_NEAR(m.amplitude_response, 1, 2 * h_mm / r);  // the integral is the staircase's area
  EXPECT_NEAR((m.quarter_set_centre_mm - target).norm(), 0, 1e-6);
}

// The same disc negated: the target's direction is the image's largest magnitude, so every
// figure but AR's sign is the same.
TEST(GreitMerit, NegativeImageIsTheTargetNegated) {
  const Vector2 target(20, 30);
  const Vector image = disc_image(target, 6);
  const GreitMerit positive = greit_figures_of_merit(square_mesh(), image, target, 1);
  const GreitMerit negative = greit_figures_of_merit(square_mesh(), -image, target, 1);
  EXPECT_EQ(negative.position_error_mm, positive.position_error_mm);
  EXPECT_EQ(negative.resolution, positive.resolution);
  EXPECT_EQ(negative.shape_deformation, positive.shape_deformation);
  EXPECT_EQ(negative.amplitude_response, positive.amplitude_response);
}

// The disc drawn 3 mm further from the sheet's centre (30, 30) than the target, then 3 mm nearer:
// PE = r_target − r_image = ∓3 mm (GREIT's sign: > 0 towards the centre). The image is the disc
// itself, so SD and RES are as on the target.
TEST(GreitMerit, ShiftedDiscGivesTheShift) {
  const Vector2 target(40, 30);
  const GreitMerit outward = greit_figures_of_merit(square_mesh(), disc_image({43, 30}, 5), target, 1);
  EXPECT_NEAR(outward.position_error_mm, -3, 1e-6);
  const GreitMerit inward = greit_figures_of_merit(square_mesh(), disc_image({37, 30}, 5), target, 1);
  EXPECT_NEAR(inward.position_error_mm, 3, 1e-6);
  EXPECT_NEAR(sheet_centre_mm(square_mesh()).x(), 30, 1e-9);
}

// A disc of 1 (r 5 mm) in a ring of −0.2 (8 to 10 mm): the quarter set is the disc, C is the disc,
// and RNG = 0.2·π(10² − 8²) / (π 5²) = 0.288. The sets' areas are their staircases' (within a few
// per cent of the discs', the staircase's errors cancelling along a rim), hence 4 %.
TEST(GreitMerit, NegativeRingGivesItsRinging) {
  const Vector2 c(25, 32);
  const Vector image = drawn([&](const Vector2& p) {
    const double d = (p - c).norm();
    return d <= 5 ? 1.0 : (d >= 8 && d <= 10 ? -0.2 : 0.0);
  });
  const GreitMerit m = greit_figures_of_merit(square_mesh(), image, c, 1);
  EXPECT_NEAR(m.ringing, 0.2 * (100 - 64) / 25.0, 0.04 * 0.288);
  EXPECT_LT(m.shape_deformation, h_mm / 5);
}

// An ellipse of semi-axes 8 and 4 mm: C has radius √32, and SD is the ellipse's share outside it,
// 1 − ½∫ min(ρ(θ), √32)² dθ / (π·8·4), ρ(θ) the ellipse's polar radius (the integral by the
// midpoint rule on 10⁵ angles, exact to 1e-6). The staircase's band moves it by under h/b.
TEST(GreitMerit, EllipseShapeDeformation) {
  const double a = 8, b = 4, c = std::sqrt(a * b);
  const int n = 100000;
  double covered = 0;
  for (int i = 0; i < n; ++i) {
    const double theta = (i + 0.5) * 2 * std::numbers::pi / n;
    const double rho = a * b / std::hypot(b * std::cos(theta), a * std::sin(theta));
    covered += 0.5 * std::pow(std::min(rho, c), 2) * 2 * std::numbers::pi / n;
  }
  const double expected = 1 - covered / (std::numbers::pi * a * b);
  const Vector image = drawn(
      [&](const Vector2& p) { return std::pow((p.x() - 30) / a, 2) + std::pow((p.y() - 30) / b, 2) <= 1 ? 1.0 : 0.0; });
  const GreitMerit m = greit_figures_of_merit(square_mesh(), image, {30, 30}, 1);
  EXPECT_GT(expected, 0.15);  // an elongated outline is far from its circle
  EXPECT_NEAR(m.shape_deformation, expected, h_mm / b);
}

TEST(GreitMerit, RejectsBadImages) {
  const Mesh& mesh = square_mesh();
  EXPECT_THROW(greit_figures_of_merit(mesh, Vector::Zero(3), {30, 30}, 1), InvalidInput);
  EXPECT_THROW(greit_figures_of_merit(mesh, Vector::Zero(mesh.triangle_count()), {30, 30}, 1), InvalidInput);
  EXPECT_THROW(greit_figures_of_merit(mesh, disc_image({30, 30}, 5), {30, 30}, 0), InvalidInput);
}

}  // namespace
}  // namespace emit
