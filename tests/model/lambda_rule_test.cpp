// λ² from the spectrum (model/lambda_rule.hpp): it follows the Jacobian's scale, and a sheet
// scaled ×2 gets the same λ² relative to its spectrum.
#include "emit/model/lambda_rule.hpp"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "emit/core/errors.hpp"
#include "emit/mesh/generate_mesh.hpp"
#include "emit/model/jacobian.hpp"
#include "emit/model/measurements.hpp"
#include "emit/model/method.hpp"
#include "emit/sensor/sensor_json.hpp"
#include "test_support.hpp"

namespace emit {
namespace {

TEST(LambdaRule, ScaleIsTheSecondEigenvalue) {
  const Vector sigma = (Vector(4) << 0.0, 2.0, 100.0, 1.0).finished();
  EXPECT_DOUBLE_EQ(spectrum_scale(sigma), 2.0);
  EXPECT_DOUBLE_EQ(automatic_lambda2(sigma, 1.5), 3.0);
  // A Jacobian c times larger has a spectrum c² times larger, and so λ².
  EXPECT_DOUBLE_EQ(automatic_lambda2(9 * sigma, 1.5), 9 * 3.0);
  EXPECT_THROW(automatic_lambda2(sigma, 0), InvalidInput);
  EXPECT_THROW(automatic_lambda2(Vector::Zero(3), 1), InvalidInput);
}

struct Spectrum {
  double scale = 0, lambda2 = 0, largest = 0;
};

Spectrum spectrum_of(const Sensor& sensor) {
  const Mesh mesh = generate_mesh(sensor, reconstruction_mesh_options(sensor));
  const MeasurementSet measurements = make_measurement_set(mesh.electrode_count());
  const OperatorFamily family(compute_jacobian(mesh, measurements), mesh, Prior::identity);
  const OperatorOptions options = operator_options(Method::paper);
  return {spectrum_scale(family.eigenvalues()), family.lambda2_for(options), family.eigenvalues().maxCoeff()};
}

// The 30 mm sheet and the same sheet ×2 (60 mm, electrodes and elements ×2): the rule's λ²
// relative to the largest eigenvalue (the spectrum's own yardstick) is the same within 15 %, the
// figure the positional error tolerates (the paper method's error doubles when λ² is 25 % off).
// A fixed λ² would be off by the ratio of the spectra's scales.
TEST(LambdaRule, SameRelativeLambdaOnASheetScaledTwice) {
  nlohmann::json j = nlohmann::json::parse(test::read_text(test::source_path("examples/sensors/square30.json")));
  j["mesh"]["element_size_mm"] = 2.0;  // ~500 triangles: quick
  const Sensor small = parse_sensor(j);
  j["shape"]["width_mm"] = 60, j["shape"]["height_mm"] = 60, j["electrodes"]["width_mm"] = 4;
  j["mesh"]["element_size_mm"] = 4.0;
  const Sensor large = parse_sensor(j);
  const Spectrum a = spectrum_of(small), b = spectrum_of(large);
  std::printf("30 mm: scale %.4g, lambda2 %.4g; 60 mm: scale %.4g, lambda2 %.4g\n", a.scale, a.lambda2, b.scale,
              b.lambda2);
  EXPECT_NEAR((b.lambda2 / b.largest) / (a.lambda2 / a.largest), 1.0, 0.15);
  EXPECT_NEAR(a.lambda2 / a.scale, operator_options(Method::paper).relative_lambda2, 1e-9);
}

}  // namespace
}  // namespace emit
