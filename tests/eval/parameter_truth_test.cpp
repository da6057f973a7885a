// A realistic sheet's truth in a calibration's own terms (eval/parameter_truth.hpp), on sheets
// whose answer is known by hand.
#include "emit/eval/parameter_truth.hpp"

#include <cmath>

#include <gtest/gtest.h>

#include "emit/core/errors.hpp"
#include "emit/model/fit_model.hpp"
#include "emit/sensor/sensor_json.hpp"

namespace emit {
namespace {

SensorCalibration named_parameters(const Mesh& mesh, int electrodes) {
  SensorCalibration c;
  c.correction = SheetCorrection::identity_over(mesh, SheetCorrection::cubic_terms);
  for (const char* term : {"u", "v", "u^2", "uv", "v^2", "u^3", "u^2 v", "u v^2", "v^3"})
    c.parameters.push_back({std::string("sheet log-conductance ") + term, 0, 0.01, 1, true});
  c.parameters.push_back({"drive_voltage_V", 3.1, 0.01, 0.3, true});
  for (int e = 0; e < electrodes; ++e) {
    c.parameters.push_back({"series_resistance_ohm[" + std::to_string(e) + "]", 100, 50, 300, true});
    c.parameters.push_back({"electrode_shift_mm[" + std::to_string(e) + "]", 0, 0.1, 0.5, true});
  }
  return c;
}

// No field, the sheet 1.3× as resistive: the log-conductance is the constant −log 1.3 (θ = 0 to
// round-off), so the model, which holds the nominal σ, sees each R·σ as R/1.3; the drive and
// the shifts are as drawn.
TEST(ParameterTruth, AUniformSheetScalesTheSeriesResistancesOnly) {
  const Sensor sensor = default_sensor();
  const Mesh mesh = fit_mesh(sensor);
  RealisticSheetOptions options;
  options.field = 0;
  options.seed = 5;
  RealisticSheet sheet = make_realistic_sheet(sensor, options);
  const SensorCalibration c = named_parameters(mesh, sensor.electrode_count());
  const std::vector<double> truth = parameter_truth(c, sheet, mesh);
  ASSERT_EQ(truth.size(), c.parameters.size());
  for (int k = 0; k < 9; ++k) EXPECT_NEAR(truth[static_cast<std::size_t>(k)], 0, 1e-12) << c.parameters[k].name;
  EXPECT_DOUBLE_EQ(truth[9], sheet.drive_voltage_V);
  for (std::size_t e = 0; e < sheet.series_ohm.size(); ++e) {
    EXPECT_NEAR(truth[10 + 2 * e], sheet.series_ohm[e] / sheet.sheet_scale, 1e-9 * sheet.series_ohm[e]);
    EXPECT_DOUBLE_EQ(truth[11 + 2 * e], sheet.shift_mm[e]);
  }
}

// A field that is one of the correction's own terms, e^{0.1 u} in conductance: θ_u = 0.1, every
// other term 0, to round-off.
TEST(ParameterTruth, AFieldOfTheCorrectionsTermsIsItsOwnTheta) {
  const Sensor sensor = default_sensor();
  const Mesh mesh = fit_mesh(sensor);
  RealisticSheetOptions options;
  options.field = 0;
  options.sheet_scale = 0;
  RealisticSheet sheet = make_realistic_sheet(sensor, options);
  const SensorCalibration c = named_parameters(mesh, sensor.electrode_count());
  const SheetCorrection box = c.correction;
  sheet.twin_options.sheet_resistance_factor = [box](const Vector2& p) { return std::exp(-0.1 * box.basis(p)[0]); };
  const std::vector<double> truth = parameter_truth(c, sheet, mesh);
  EXPECT_NEAR(truth[0], 0.1, 1e-12);
  for (int k = 1; k < 9; ++k) EXPECT_NEAR(truth[static_cast<std::size_t>(k)], 0, 1e-12) << c.parameters[k].name;
}

// Coverage counted by hand: off by 0.5σ, 1.5σ and 3σ.
TEST(ParameterTruth, CoverageCountsWithinOneAndTwoSigma) {
  SensorCalibration c;
  c.parameters = {{"a", 1.0, 0.2, 1, true}, {"b", 1.0, 0.2, 1, true}, {"c", 1.0, 0.2, 1, true}};
  const ParameterCoverage coverage = parameter_coverage(c, {1.1, 0.7, 1.6});
  EXPECT_EQ(coverage.parameters, 3);
  EXPECT_EQ(coverage.within_1_sigma, 1);
  EXPECT_EQ(coverage.within_2_sigma, 2);
  EXPECT_THROW(parameter_coverage(c, {1.0}), InvalidInput);
}

}  // namespace
}  // namespace emit
