// Readings a frame cannot be trusted with: filled by their mean given the others under the
// operator's prior, the image is exactly that of the operator built without them (the identity
// and the Laplacian prior: a Q that does not depend on J's rows, as NOSER's does); the reconstructor masks a board's
// glitches (a dropped reading, a clipped one, a grounding that failed for one frame) and places the press as in the
// clean frame, allocating nothing.
#include "emit/frame/masked_readings.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <vector>

#include <gtest/gtest.h>

#include "allocation_counter.hpp"
#include "emit/core/errors.hpp"
#include "emit/frame/reconstructor.hpp"
#include "emit/model/jacobian.hpp"
#include "emit/model/method.hpp"
#include "emit/model/reconstruction_model.hpp"
#include "emit/sensor/adc.hpp"
#include "emit/sensor/sensor_json.hpp"
#include "emit/twin/twin.hpp"

namespace emit {
namespace {

Sensor small_sensor() {
  Sensor sensor = default_sensor();
  sensor.mesh.element_size_mm = 3.0;  // small and quick
  return sensor;
}

TEST(MaskedReadings, TheImageIsThatOfTheOperatorWithoutThem) {
  const Sensor sensor = small_sensor();
  Twin twin(sensor);
  const Frame reference = twin.frame({});
  const Frame pressed = twin.frame({{22, 35, 5, 10}});
  for (const Method method : {Method::paper, Method::laplacian}) {  // Q of the mesh, not of J (NOSER's)
    const ReconstructionModel model = build_reconstruction_model(sensor, operator_options(method), "");
    const Matrix J = compute_jacobian(model.mesh, model.measurements);
    OperatorOptions options = model.options;  // with the λ² it chose: R' has the same
    const Matrix R = build_reconstruction_operator(J, model.mesh, options);
    const Vector dV = frame_difference(model.measurements, pressed, reference);
    const std::vector<Index> masked = {3, 17, 18, 120, 201, 239};  // two of one row, spread over the rest
    std::vector<Index> kept;
    for (Index m = 0; m < dV.size(); ++m)
      if (std::find(masked.begin(), masked.end(), m) == masked.end()) kept.push_back(m);
    Matrix J_kept(static_cast<Index>(kept.size()), J.cols());
    Vector dV_kept(static_cast<Index>(kept.size()));
    for (std::size_t i = 0; i < kept.size(); ++i)
      J_kept.row(static_cast<Index>(i)) = J.row(kept[i]), dV_kept(static_cast<Index>(i)) = dV(kept[i]);
    const Vector truth = build_reconstruction_operator(J_kept, model.mesh, options) * dV_kept;

    Vector filled = dV;
    for (const Index m : masked) filled(m) = std::nan("");  // ignored
    MaskedReadingFill fill(dV.size(), 16);
    fill.fill(model.op.precision(), masked, filled);
    Vector zeroed = dV;
    for (const Index m : masked) zeroed(m) = 0;
    const double error = (R * filled - truth).norm() / truth.norm();
    const double naive = (R * zeroed - truth).norm() / truth.norm();
    std::printf("%s: masked 6 of %lld readings: the image %.2g from the reduced operator's (zeros instead: %.2g)\n",
                method_name(method), static_cast<long long>(dV.size()), error, naive);
    // P is stored in single precision (relative rounding 6e-8 per entry): the fill of 6 of 240
    // readings carries it, 1e-6 of the image bounds it (measured 1e-9, both priors). Zeros in
    // their place are off by 0.1, so the test can tell.
    EXPECT_LT(error, 1e-6);
    EXPECT_GT(naive, 10 * error);
    for (const Index m : masked) EXPECT_TRUE(std::isfinite(filled(m)));
  }
  MaskedReadingFill small(10, 2);
  Vector v = Vector::Zero(10);
  EXPECT_THROW(small.fill(Eigen::MatrixXf::Identity(10, 10), {1, 2, 3}, v), InvalidInput);  // beyond its scratch
  EXPECT_THROW(small.fill(Eigen::MatrixXf::Identity(9, 9), {1}, v), InvalidInput);          // another size
}

// A board's glitches in one frame of a press: two dropped readings (NaN), two clipped at the top
// code, and a grounding that failed (its whole row at full scale). Masked, the paper method
// places the press where it places it in the clean frame, to a tenth of its own error (3.3 mm
// on this sheet); the glitched values used as readings put it millimetres off or lose it.
TEST(MaskedReadings, TheReconstructorMasksABoardsGlitches) {
  const Sensor sensor = small_sensor();
  const ReconstructionModel model = build_reconstruction_model(sensor, operator_options(Method::paper), "");
  Twin twin(sensor);
  Reconstructor reconstructor(model, LinearCalibration::uncalibrated(sensor));
  reconstructor.set_reference({twin.frame({}), 1});
  const Frame clean = twin.frame({{35, 25, 5, 10}});
  const auto clean_contacts = reconstructor.process(clean);
  ASSERT_EQ(clean_contacts.size(), 1u);
  const Contact expected = clean_contacts[0];
  EXPECT_TRUE(reconstructor.masked_readings().empty());

  Frame glitched = clean;
  glitched(2, 9) = glitched(11, 4) = std::nan("");
  glitched(5, 6) = glitched(12, 13) = sensor.adc.vref_V;  // the top code
  glitched.row(7).setConstant(sensor.adc.vref_V);         // ground 7 not grounded in this frame
  glitched(7, 7) = 0;
  reconstructor.process(glitched);  // warm-up: the first masked frame
  test::AllocationCounter counter;
  const auto& contacts = reconstructor.process(glitched);
  EXPECT_EQ(counter.count(), 0);
  EXPECT_EQ(reconstructor.masked_readings().size(), 4u + 15u);
  ASSERT_EQ(contacts.size(), 1u);
  const double moved_mm = std::hypot(contacts[0].x_mm - expected.x_mm, contacts[0].y_mm - expected.y_mm);
  std::printf("clean (%.2f, %.2f) mm; 19 readings masked: moved %.3f mm\n", expected.x_mm, expected.y_mm, moved_mm);
  EXPECT_LT(moved_mm, 0.33);

  // The same values read as true (a reconstructor whose ADC's top code is out of reach, the NaNs
  // as the clean frame's): the clipped row alone moves or splits the press.
  ReconstructionModel unmasked = model;
  unmasked.clipped_at_V = std::numeric_limits<double>::infinity();
  Reconstructor naive(unmasked, LinearCalibration::uncalibrated(sensor));
  naive.set_reference({twin.frame({}), 1});
  Frame as_read = glitched;
  as_read(2, 9) = clean(2, 9), as_read(11, 4) = clean(11, 4);
  const auto& wrong = naive.process(as_read);
  const double naive_mm =
      wrong.empty() ? INFINITY : std::hypot(wrong[0].x_mm - expected.x_mm, wrong[0].y_mm - expected.y_mm);
  std::printf("the clipped readings used: %zu contacts, the first %.1f mm off\n", wrong.size(), naive_mm);
  EXPECT_TRUE(wrong.size() != 1 || naive_mm > 10 * moved_mm);

  // More than half the readings masked: the frame tells nothing.
  Frame lost = Frame::Constant(16, 16, std::nan(""));
  EXPECT_TRUE(reconstructor.process(lost).empty());
  EXPECT_EQ(reconstructor.masked_readings().size(), 240u);
}

}  // namespace
}  // namespace emit
