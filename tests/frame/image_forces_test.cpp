// A linear image's contacts given their force by the force law (frame/image_forces.hpp): each
// contact's share of the image's integral, exact on a sheet of square cells; the force, area,
// pressures and σs from the law; strongest first; its checks; no allocation per frame.
#include "emit/frame/image_forces.hpp"

#include <numbers>
#include <vector>

#include <gtest/gtest.h>

#include "allocation_counter.hpp"
#include "emit/core/errors.hpp"
#include "test_support.hpp"

namespace emit {
namespace {

/// A 40 × 30 mm sheet of 1 mm square cells, two triangles each: 1,200 mm².
Mesh sheet() { return test::strip_mesh(40.0, 30.0, 40, 30); }

Contact contact_at(double x_mm, double y_mm) {
  Contact c;
  c.x_mm = x_mm, c.y_mm = y_mm;
  return c;
}

/// 1 left of x = 20 mm, 2 right of it (no triangle straddles the line).
Vector two_levels(const Mesh& mesh) {
  Vector image(mesh.triangle_count());
  for (Index k = 0; k < image.size(); ++k) image[k] = mesh.triangle_centroid_mm(k).x() < 20 ? 1.0 : 2.0;
  return image;
}

// One contact takes the whole sheet's integral, Σ A_k δφ_k: 600·1 + 600·2. Two contacts split
// the sheet along the line halfway between them, x = 20 mm (cell edges): 600 and 1,200, exactly
// but for the sums' rounding.
TEST(ImageForces, EachContactTakesTheIntegralNearestIt) {
  const Mesh mesh = sheet();
  ImageForces forces(mesh);
  const Vector image = two_levels(mesh);
  EXPECT_NEAR(forces.integrals(image, {contact_at(12, 3)})[0], 1800, 1e-9);
  const std::vector<double> two = forces.integrals(image, {contact_at(10, 15), contact_at(30, 15)});
  ASSERT_EQ(two.size(), 2u);
  EXPECT_NEAR(two[0], 600, 1e-9);
  EXPECT_NEAR(two[1], 1200, 1e-9);
  EXPECT_TRUE(forces.integrals(image, {}).empty());
}

// F = (b1/I + b2)^b3 with b1 = 1200, b2 = 0, b3 = −1: F = I/1200, so 0.5 N and 1 N; each
// reported with the indenter's area, its pressure F/A peak and mean, the σs from the law;
// the stronger (right) contact first; position and element count as found.
TEST(ImageForces, ApplyReportsTheLawsForceAtTheIndentersArea) {
  const Mesh mesh = sheet();
  ImageForces forces(mesh);
  ImageForceLaw law;
  law.b1_V_mm2 = 1200, law.b2 = 0, law.b3 = -1, law.log_std = 0.1, law.indenter_radius_mm = 2;
  Contact left = contact_at(10, 15), right = contact_at(30, 15);
  left.element_count = 7, right.element_count = 9;
  const std::vector<Contact>& out = forces.apply(law, two_levels(mesh), {left, right});
  ASSERT_EQ(out.size(), 2u);
  const double area = 4 * std::numbers::pi;
  EXPECT_EQ(out[0].x_mm, 30);
  EXPECT_EQ(out[0].element_count, 9);
  EXPECT_NEAR(out[0].force_N, 1.0, 1e-12);
  EXPECT_NEAR(out[1].force_N, 0.5, 1e-12);
  for (const Contact& c : out) {
    EXPECT_DOUBLE_EQ(c.area_mm2, area);
    EXPECT_DOUBLE_EQ(c.pressure_N_per_mm2, c.force_N / area);
    EXPECT_DOUBLE_EQ(c.peak_pressure_N_per_mm2, c.pressure_N_per_mm2);
    EXPECT_DOUBLE_EQ(c.force_std_N, law.force_relative_std() * c.force_N);
    EXPECT_DOUBLE_EQ(c.pressure_std_N_per_mm2, law.pressure_relative_std() * c.pressure_N_per_mm2);
  }
}

TEST(ImageForces, ImageOfTheWrongSizeIsRefused) {
  ImageForces forces(sheet());
  EXPECT_EQ(test::error_of([&] { forces.integrals(Vector::Zero(5), {contact_at(1, 1)}); }),
            "image forces: the image has 5 values, expected one per mesh element (2400)");
}

// docs/architecture.md: the online path allocates nothing per frame.
TEST(ImageForces, ApplyAllocatesNothing) {
  const Mesh mesh = sheet();
  ImageForces forces(mesh);
  const Vector image = two_levels(mesh);
  const std::vector<Contact> contacts{contact_at(10, 15), contact_at(30, 15), contact_at(20, 5)};
  const ImageForceLaw law;
  forces.apply(law, image, contacts);  // warm-up
  test::AllocationCounter counter;
  const std::vector<Contact>& out = forces.apply(law, image, contacts);
  EXPECT_EQ(counter.count(), 0);
  EXPECT_EQ(out.size(), 3u);
}

}  // namespace
}  // namespace emit
