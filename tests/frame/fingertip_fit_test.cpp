// Contact fitting on a sheet from a CAD file (sensor/height_field.hpp): the committed fingertip,
// a half capsule of radius 9 mm (examples/sensors/make_fingertip.cpp), pressed on its pad, on its
// tip's sphere, on its sides and near its back.
#include <cmath>
#include <cstdio>

#include <gtest/gtest.h>

#include "emit/mesh/sheet_file.hpp"
#include "emit/pipeline/pipeline.hpp"
#include "emit/sensor/press.hpp"
#include "emit/sensor/surface.hpp"
#include "emit/twin/twin.hpp"
#include "test_support.hpp"

namespace emit {
namespace {

/// The capsule's outward normal at p: from the x axis on the cylinder (x ≤ 0), from the centre
/// on the tip's sphere.
Vector3 capsule_normal(const Vector3& p) { return p.x() <= 0 ? Vector3(0, p.y(), p.z()).normalized() : p.normalized(); }

// Presses of r = 2.5 mm at least 2.5 mm from the border. The twin's mesh is another (twice as
// fine, graded); the bound is the spherical cap's target, 0.3 mm. The fitted normal is the
// reconstruction triangle's: on edges h ≤ 1 mm of a radius of 9 mm it turns by at most h/R.
TEST(FingertipFit, PressesAreFoundWhereTheyAreOnTheCadSkin) {
  const Sensor sensor = load_sheet_sensor(test::source_path("examples/sensors/fingertip.json"));
  Pipeline pipeline(sensor, {Method::fit, 0, "", {}});
  Reconstructor reconstructor = pipeline.reconstructor();
  Twin twin(sensor);
  reconstructor.set_reference({twin.exact_frame({}), 1});
  for (const Vector2& c : {Vector2(0, 0), Vector2(-8, 4), Vector2(5, -3), Vector2(-11, -5), Vector2(3, 4.5)}) {
    const Press press = press_at_chart(sensor.shape, c, 2.5, 2);
    const Vector3 p(press.x_mm, press.y_mm, press.z_mm);
    const auto& contacts = reconstructor.process(twin.exact_frame({press}));
    ASSERT_EQ(contacts.size(), 1u) << c.transpose();
    const Contact& contact = contacts[0];
    const Vector3 found(contact.x_mm, contact.y_mm, contact.z_mm);
    const double error_mm = (found - p).norm();
    const double turn = (Vector3(contact.nx, contact.ny, contact.nz) - capsule_normal(found)).norm();
    std::printf("fingertip press at (%.1f, %.1f, %.2f): error %.3f mm, normal off by %.3f\n", p.x(), p.y(), p.z(),
                error_mm, turn);
    EXPECT_LT(error_mm, 0.3);
    EXPECT_LT(turn, 1.0 / 9);
  }
}

}  // namespace
}  // namespace emit
