// `emit eval` on one sheet (eval/sheet_evaluation.hpp), in-process on a coarse 30 mm sheet with
// the paper method over a two-point λ² sweep: the cases, the sweep, pressure and two presses, and
// the plots. (Contact fitting's evaluation runs end to end in tests/cli/cli_test.cpp,
// Cli.EvalMeasuresContactFitting; the mismatches themselves are tests/twin/sensor_mismatch_test.cpp's,
// their evaluation, five more twins, is left to `emit eval` to keep the suite quick.)
#include "emit/eval/sheet_evaluation.hpp"

#include <cmath>
#include <cstdio>
#include <filesystem>

#include <gtest/gtest.h>

#include "emit/render/image.hpp"
#include "emit/sensor/sensor_json.hpp"
#include "test_support.hpp"

namespace emit {
namespace {

TEST(SheetEvaluation, StandardCasesAreTheSevenSheets) {
  const auto cases = standard_eval_cases(test::source_path("examples/sensors"));
  ASSERT_EQ(cases.size(), 7u);
  EXPECT_EQ(cases[6].sensor.shape.kind, ShapeKind::mesh_file);
  EXPECT_TRUE(cases[6].sensor.shape.surface);  // read with its sensor: press scripts need its outline
  EXPECT_EQ(cases[4].sensor.shape.kind, ShapeKind::spherical_cap);
  EXPECT_EQ(cases[5].sensor.shape.kind, ShapeKind::cylinder);
  EXPECT_EQ(cases[5].sensor.shape.angle_deg, 360.0);
  EXPECT_EQ(cases[1].name, "30 x 30 mm sheet");
  EXPECT_EQ(cases[1].sensor.electrode_count(), 16);
  EXPECT_EQ(cases[3].sensor.electrode_count(), 32);
  EXPECT_FALSE(cases[2].pressure_and_two_press);
}

EvalCase coarse_30mm_case() {
  EvalCase c;
  c.name = "coarse 30 mm";
  c.sensor = load_sensor(test::source_path("examples/sensors/square30.json"));
  c.sensor.mesh.element_size_mm = 2.0;  // ~500 triangles: quick
  c.spacing_mm = 5;
  c.jitter_mm = 1;
  c.radius_mm = 2.5;
  return c;
}

// No λ² given: the rule's (model/lambda_rule.hpp) on the coarse 30 mm sheet, against a sweep of
// 16 a decade around it. Targets: within 15 % of the sweep's best error; false
// contacts on at most 5 % of single presses and of no-press frames; the same error (±10 %)
// with the reference from ten frames one of which is very noisy, and from any one frame alone.
TEST(SheetEvaluation, AutomaticLambdaNearTheSweepsBest) {
  EvalCase c = coarse_30mm_case();
  c.sensor.mesh.element_size_mm = 0.6;  // the sheet's own mesh: the rule was measured on it
  c.sensor.mesh.twin_refinement = 1.5;
  EvalOptions options;
  options.methods = {Method::paper};
  for (int i = 0; i <= 16; ++i) options.lambda2.push_back(5e3 * std::pow(10.0, i / 32.0));  // 5·10³ … 1.6·10⁴
  options.quick = true;
  options.mismatches = false;
  const MethodEvaluation m = evaluate_sheet(c, options).methods.at(0);
  std::printf(
      "auto lambda2 %.4g: %.2f mm; sweep's best %.4g: %.2f mm; false contacts %.2f, no-press %.2f; "
      "single reference %.2f..%.2f mm, one noisy of ten %.2f mm\n",
      m.auto_lambda2, m.auto_position.mean, m.lambda2, m.position.mean, m.false_contacts, m.noise_contacts,
      m.single_reference_low_mm, m.single_reference_high_mm, m.noisy_reference_mm);
  EXPECT_LE(m.auto_position.mean, 1.15 * m.position.mean);
  EXPECT_LE(m.false_contacts, 0.05);
  EXPECT_LE(m.noise_contacts, 0.05);
  EXPECT_NEAR(m.noisy_reference_mm, m.auto_position.mean, 0.1 * m.auto_position.mean);
  EXPECT_NEAR(m.single_reference_low_mm, m.auto_position.mean, 0.1 * m.auto_position.mean);
  EXPECT_NEAR(m.single_reference_high_mm, m.auto_position.mean, 0.1 * m.auto_position.mean);
}

TEST(SheetEvaluation, PaperMethodSweepAndPlots) {
  const EvalCase c = coarse_30mm_case();
  EvalOptions options;
  options.methods = {Method::paper};
  options.lambda2 = {1e3, 1e4};
  options.quick = true;
  options.mismatches = false;
  const SheetEvaluation e = evaluate_sheet(c, options);
  EXPECT_GT(e.grid_presses, 0u);
  EXPECT_GT(e.triangles, 0);
  ASSERT_EQ(e.methods.size(), 1u);
  const MethodEvaluation& paper = e.methods[0];
  std::
      printf("coarse 30 mm sheet, paper method at λ² %g: %.2f +/- %.2f mm over %d presses, pressure error %.3f N/mm2\n",
             paper.lambda2, paper.position.mean, paper.position.std, paper.position.count,
             paper.pressure_error_N_per_mm2.value_or(-1));
  ASSERT_EQ(paper.sweep.size(), 2u);
  // The best of the sweep is kept, and would be used for the mismatches.
  EXPECT_EQ(paper.position.mean, std::min(paper.sweep[0].image_centroid.mean, paper.sweep[1].image_centroid.mean));
  EXPECT_EQ(e.mismatch_lambda2, paper.lambda2);
  // The paper reports 1.74 mm on its 30 mm sheet; a coarse mesh may do worse, but a broken
  // pipeline is off by the sheet's size. Bound: twice the paper's figure.
  EXPECT_EQ(paper.position.missed, 0);
  EXPECT_LT(paper.position.mean, 2 * 1.74);
  for (const SweepPoint& p : paper.sweep) {
    EXPECT_GT(p.l_curve.residual_norm_V, 0.0);
    EXPECT_GT(p.l_curve.solution_norm_V, 0.0);
  }
  // A larger λ² shrinks the image and leaves more misfit (the L-curve's two ends).
  EXPECT_LT(paper.sweep[1].l_curve.solution_norm_V, paper.sweep[0].l_curve.solution_norm_V);
  EXPECT_GT(paper.sweep[1].l_curve.residual_norm_V, paper.sweep[0].l_curve.residual_norm_V);
  ASSERT_TRUE(paper.pressure_error_N_per_mm2.has_value());
  // A fifth of the presses' 0.5 N/mm² full scale (emit eval's paper method: 0.076 on the 60 mm sheet).
  EXPECT_LT(*paper.pressure_error_N_per_mm2, 0.1);
  ASSERT_TRUE(paper.two_press.has_value());
  EXPECT_EQ(paper.two_press->frames, 10);  // quick: 10 two-finger frames
  // After `emit calibrate` on the 10 calibration presses, the 10 test presses' force from the
  // image's integral (model/force_law.hpp) within issue 31's 15 %; eq. 8 summed over the 50 %
  // region, as before, is the image's force, further off.
  ASSERT_TRUE(paper.calibrated.has_value() && paper.equation_8_forces.has_value());
  std::printf("calibrated force error %.1f %% (eq. 8 over the region %.0f %%)\n", 100 * paper.calibrated->force_error,
              100 * paper.equation_8_forces->force_error);
  EXPECT_EQ(paper.calibrated->frames, 10);
  EXPECT_LT(paper.calibrated->force_error, 0.15);
  EXPECT_GT(paper.equation_8_forces->force_error, paper.calibrated->force_error);

  EXPECT_TRUE(e.mismatches.empty());

  const std::string dir = test::temp_folder("sheet_evaluation") + "/plots";
  const auto plots = write_sweep_plots(c, e, dir);
  ASSERT_EQ(plots.size(), 2u);
  EXPECT_EQ(plots[0], dir + "/coarse_30_mm_error_vs_lambda.png");
  for (const std::string& plot : plots) EXPECT_GT(read_png(plot).width(), 100) << plot;
}

// Contact fitting alone sweeps no λ²: there is nothing to plot, and no folder is made.
TEST(SheetEvaluation, NoPlotsWithoutASweep) {
  SheetEvaluation e;
  e.methods.push_back(MethodEvaluation{});
  e.methods[0].method = Method::fit;
  const std::string dir = test::temp_folder("sheet_evaluation_none") + "/plots";
  EXPECT_TRUE(write_sweep_plots(coarse_30mm_case(), e, dir).empty());
  EXPECT_FALSE(std::filesystem::exists(dir));
}

}  // namespace
}  // namespace emit
