// The linear methods' force after `emit calibrate` (issue 31: "paper force ≤ 15 % on indenters
// like its calibration's"): on the 60 mm sheet, twin frames on a mesh other than the
// reconstruction's, each of paper, NOSER and Laplacian calibrated on 30 presses of a 5 mm disc,
// 4–16 N at random places (pipeline/press_calibration.hpp), then 10 held-out presses reconstructed
// as `emit reconstruct` does (Pipeline): their force from the image's integral by emit's force
// law (model/force_law.hpp). Eq. 8 summed over the 50 % region, as before the force law, is
// measured on the same presses to show the bound is not met by accident.
#include <cmath>
#include <cstdio>
#include <variant>

#include <gtest/gtest.h>

#include "emit/pipeline/pipeline.hpp"
#include "emit/pipeline/press_calibration.hpp"
#include "emit/sensor/sensor_json.hpp"
#include "emit/twin/press_scripts.hpp"
#include "emit/twin/twin.hpp"
#include "test_support.hpp"

namespace emit {
namespace {

/// Mean |F̂/F − 1| of the strongest contact over single-press frames; a frame without a contact
/// counts as a 100 % error.
double mean_force_error(Reconstructor& reconstructor, const std::vector<Frame>& frames, const PressSequence& truth) {
  double sum = 0;
  for (std::size_t f = 0; f < frames.size(); ++f) {
    const std::vector<Contact>& contacts = reconstructor.process(frames[f]);
    sum += contacts.empty() ? 1.0 : std::abs(contacts.front().force_N / truth[f][0].force_N - 1);
  }
  return sum / static_cast<double>(frames.size());
}

TEST(LinearForce, WithinFifteenPercentOnHeldOutPressesOfTheCalibrationsIndenter) {
  const Sensor sensor = default_sensor();
  TwinOptions twin_options;
  twin_options.mesh_seed = 3;  // finer than and different from the reconstruction's mesh
  twin_options.noise_seed = 17;
  Twin twin(sensor, twin_options);
  std::vector<Frame> untouched;
  untouched.reserve(10);
  for (int i = 0; i < 10; ++i) untouched.push_back(twin.frame({}));
  const Reference reference = average_reference(untouched);
  PressStyle style;
  style.radius_mm = 5, style.margin_mm = 6, style.min_force_N = 4, style.max_force_N = 16, style.seed = 31;
  const PressSequence calibration_presses = random_script(sensor, 30, style);
  style.seed = 32;
  const PressSequence held_out = random_script(sensor, 10, style);
  std::vector<Frame> calibration_frames, held_out_frames;
  for (const auto& presses : calibration_presses) calibration_frames.push_back(twin.frame(presses));
  for (const auto& presses : held_out) held_out_frames.push_back(twin.frame(presses));

  const std::string cache = test::temp_folder("linear_force_cache");  // the operator built once a method
  for (const Method method : {Method::paper, Method::noser, Method::laplacian}) {
    PressCalibrationOptions options;
    options.method = method;
    options.cache_dir = cache;
    const PressCalibrationResult calibration =
        calibrate_from_presses(sensor, options, reference, calibration_frames, calibration_presses);
    auto linear = std::get<LinearCalibration>(calibration.calibration);
    ASSERT_TRUE(linear.force_law.has_value());
    EXPECT_EQ(calibration.force_presses, 30u);  // every calibration press showed a contact
    EXPECT_NEAR(linear.force_law->indenter_radius_mm, 5, 1e-12);
    const Pipeline pipeline(sensor, {method, 0, cache, {}}, calibration.calibration);
    Reconstructor reconstructor = pipeline.reconstructor();
    reconstructor.set_reference(reference);
    const double error = mean_force_error(reconstructor, held_out_frames, held_out);
    linear.force_law.reset();  // eq. 8 alone: force Σ P_k A_k over the 50 % region
    Reconstructor equation_8(pipeline.model(), linear);
    equation_8.set_reference(reference);
    const double equation_8_error = mean_force_error(equation_8, held_out_frames, held_out);
    std::printf(
        "%s: mean |force error| %.1f %% on 10 held-out presses (calibration %.1f %%); eq. 8 over the "
        "region %.0f %%\n",
        method_name(method), 100 * error, 100 * calibration.force_error, 100 * equation_8_error);
    EXPECT_LE(error, 0.15) << method_name(method);            // issue 31's bound
    EXPECT_GT(equation_8_error, 1.0) << method_name(method);  // the image's force: several times the press's
  }
}

}  // namespace
}  // namespace emit
