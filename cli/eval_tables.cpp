// `emit eval`'s tables: per sheet, each method's errors beside the paper's (with the automatic
// λ², the significance test and the reference's averaging), and the mismatch runs; a real skin's
// held-out error and its curve against the number of calibration presses.
#include <cmath>
#include <cstdio>
#include <string>

#include "commands.hpp"
#include "emit/jobs/eval_job.hpp"
#include "emit/jobs/real_eval_job.hpp"

namespace emit::cli {

namespace {

/// The automatic λ² (no --lambda2) beside the sweep's best, and what the significance test and
/// the reference's averaging do.
void print_automatic(const MethodEvaluation& m) {
  const double best_relative = m.spectrum_scale > 0 ? m.lambda2 / m.spectrum_scale : 0;
  const double relative = m.spectrum_scale > 0 ? m.auto_lambda2 / m.spectrum_scale : 0;
  std::printf("    auto lambda2 %9.3g (%.3g x spectrum scale; best %.3g): %5.2f mm, %+.0f %% of the best\n",
              m.auto_lambda2, relative, best_relative, m.auto_position.mean,
              m.position.mean > 0 ? 100 * (m.auto_position.mean / m.position.mean - 1) : 0.0);
  std::printf(
      "      false contacts: %4.1f %% of single presses (every region: %4.1f %%), "
      "%4.1f %% of no-press frames (%4.1f %%)\n",
      100 * m.false_contacts, 100 * m.false_contacts_untested, 100 * m.noise_contacts, 100 * m.noise_contacts_untested);
  std::printf("      reference: one frame alone %.2f .. %.2f mm; ten with one very noisy %.2f mm",
              m.single_reference_low_mm, m.single_reference_high_mm, m.noisy_reference_mm);
  if (m.auto_two_press)
    std::printf("; two presses %3.0f %% found, %3.0f %% matched", 100 * m.auto_two_press->two_contacts,
                100 * m.auto_two_press->both_matched);
  std::printf("\n");
}

/// A linear method's test presses after `emit calibrate`: force by emit's force law, and by eq. 8
/// summed over the 50 % region (as before the force law).
void print_linear_forces(const SinglePressScore& law, const SinglePressScore& equation_8) {
  std::printf(
      "      calibrated force: %4.1f %% mean |error| (bias %+.1f %%; within 1 sigma %3.0f %%, 2 sigma %3.0f %%), "
      "pressure F/A %.4f N/mm2; eq. 8 summed over the 50 %% region: %.1f %% (x%.2f)\n",
      100 * law.force_error, 100 * law.force_bias, 100 * law.within_1_sigma, 100 * law.within_2_sigma,
      law.pressure_error_N_per_mm2, 100 * equation_8.force_error, 1 + equation_8.force_bias);
}

void print_method(const EvalCase& c, const MethodEvaluation& m, bool sweep) {
  if (sweep)
    for (const SweepPoint& p : m.sweep)
      std::printf("    %-10s lambda2 %9.3g: %6.2f +/- %5.2f mm (contact: %6.2f mm)\n", method_name(m.method), p.lambda2,
                  p.image_centroid.mean, p.image_centroid.std, p.strongest_contact.mean);
  char lambda[16] = "-";
  if (is_linear(m.method)) std::snprintf(lambda, sizeof lambda, "%9.3g", m.lambda2);
  const ErrorStats& e = m.position;
  std::printf("  %-10s %9s  %5.2f +/- %4.2f  %6.2f %6.2f  %6.2f  ", method_name(m.method), lambda, e.mean, e.std,
              e.median, e.p95, m.strongest_contact.mean);
  if (c.pressure_and_two_press && m.pressure_error_N_per_mm2 && m.two_press)
    std::printf("%7.4f (%4.1f %%)  %5.0f %%  %5.0f %%", *m.pressure_error_N_per_mm2,
                100 * *m.pressure_error_N_per_mm2 / 0.5, 100 * m.two_press->two_contacts,
                100 * m.two_press->both_matched);
  if (!is_linear(m.method))
    std::printf("  (%.0f ms a frame, %ld mesh nodes; 2 match: within 2 mm)", m.ms_per_frame, m.fit_mesh_nodes);
  std::printf("\n");
  if (m.three_presses || m.four_presses || m.false_regions) {
    const auto rate = [](const std::optional<double>& r) { return r ? 100 * *r : std::nan(""); };
    std::printf(
        "      three presses all found within 2 mm %3.0f %%, four %3.0f %% (%d frames each); "
        "false regions on single presses %4.1f %% of %d\n",
        rate(m.three_presses), rate(m.four_presses), m.several_press_frames, rate(m.false_regions),
        m.single_press_frames);
  }
  if (is_linear(m.method)) print_automatic(m);
  if (m.calibrated && m.equation_8_forces) print_linear_forces(*m.calibrated, *m.equation_8_forces);
}

void print_mismatches(const SheetEvaluation& e) {
  std::printf("  mismatches (twin differs, reconstruction nominal; paper at lambda2 = %.3g):\n", e.mismatch_lambda2);
  for (const MismatchEvaluation& m : e.mismatches) {
    std::printf("    %-46s %5.2f +/- %4.2f mm (median %.2f, p95 %.2f)%s\n", m.name.c_str(), m.paper.mean, m.paper.std,
                m.paper.median, m.paper.p95, m.dead_electrode_found ? ", dead electrode found and left out" : "");
    if (m.fit && m.fit_self_calibrated)
      std::printf(
          "    %46s fit: %5.2f +/- %4.2f mm (p95 %.2f); sheet self-calibrated (x%.2f..%.2f): %5.2f +/- %4.2f mm "
          "(p95 %.2f)\n",
          "", m.fit->mean, m.fit->std, m.fit->p95, m.sheet_factor_low, m.sheet_factor_high, m.fit_self_calibrated->mean,
          m.fit_self_calibrated->std, m.fit_self_calibrated->p95);
  }
}

void print_stats(const char* what, const ErrorStats& e) {
  std::printf("  %-44s %6.2f +/- %5.2f mm (median %.2f, p95 %.2f; %d presses%s)\n", what, e.mean, e.std, e.median,
              e.p95, e.count, e.missed > 0 ? (", " + std::to_string(e.missed) + " not found").c_str() : "");
}

/// "degree 6", or "kernel 30 mm, smoothing 0.0001".
std::string response_name(const PressResponseCandidate& c) {
  if (c.kernel_length_mm == 0) return "degree " + std::to_string(c.degree);
  char text[64];
  std::snprintf(text, sizeof text, "kernel %g mm, smoothing %g", c.kernel_length_mm, c.smoothing);
  return text;
}

/// The readings masked and dropped (model/reading_screen.hpp), with a warning on stderr naming
/// the worst channels when any was.
void print_reading_survey(const RealEvaluation& e) {
  const ReadingSurvey& s = e.survey;
  const std::vector<Index> dropped = s.dropped(), worst = s.worst(5);
  std::printf("  readings: %ld masked in %ld of %ld frames%s", static_cast<long>(s.masked_readings),
              static_cast<long>(s.frames_with_bad), static_cast<long>(e.presses),
              s.rail_found ? "" : (std::isfinite(s.screen.rail) ? "; rail as stated" : "; no rail found"));
  if (s.rail_found) std::printf("; rail found at %g", s.screen.rail);
  std::printf("; %zu channels dropped\n", dropped.size());
  if (worst.empty()) return;
  std::string named;
  for (const Index m : worst)
    named += (named.empty() ? "" : ", ") + std::to_string(m) + " (" +
             std::to_string(s.bad_frames[static_cast<std::size_t>(m)]) +
             (s.bad_frames[static_cast<std::size_t>(m)] == 1 ? " frame" : " frames") +
             (s.screen.is_dropped(m) ? ", dropped" : "") + ")";
  std::fprintf(stderr,
               "emit: warning: readings that cannot be used (not positive, not finite or at the rail) were left out; "
               "worst channels: %s\n",
               named.c_str());
  if (!e.unusable_calibration_presses.empty())
    std::fprintf(stderr, "emit: warning: %zu calibration presses had no reading to use and were left out\n",
                 e.unusable_calibration_presses.size());
}

}  // namespace

void print_sheet_evaluation(const EvalCase& eval_case, const SheetEvalReport& report, bool sweep) {
  const EvalCase& c = eval_case;
  const SheetEvaluation& e = report.evaluation;
  std::printf("  %zu single presses (r = %.1f mm), reconstruction mesh %ld triangles\n", e.grid_presses, c.radius_mm,
              e.triangles);
  std::printf("  %-10s %9s  %13s  %6s %6s  %6s  %16s  %6s  %6s\n", "method", "lambda2", "mean +/- std", "median", "p95",
              "contact", "pressure N/mm2", "2 found", "2 match");
  for (const MethodEvaluation& m : e.methods) print_method(c, m, sweep);
  if (report.plots.size() >= 2) std::printf("  plots: %s, %s\n", report.plots[0].c_str(), report.plots[1].c_str());
  if (!e.mismatches.empty()) print_mismatches(e);
}

void print_real_evaluation(const RealEvalJob& job, const RealEvalReport& report) {
  const RealEvaluation& e = report.evaluation;
  std::printf("emit eval --real %s: %s, %ld presses of %ld readings; calibrated on presses 0-%ld, held out %ld-%ld\n",
              job.folder.c_str(), report.sensor_name.c_str(), static_cast<long>(e.presses),
              static_cast<long>(e.readings), static_cast<long>(e.calibration_presses - 1),
              static_cast<long>(e.test_from), static_cast<long>(e.presses - 1));
  print_reading_survey(e);
  std::printf("  press response: %s, shrinkage %.1f (chosen by %d-fold cross-validation: %.2f mm); drift rate %.2f\n",
              response_name(e.fit.kept).c_str(), e.fit.kept.shrinkage, job.options.fit.folds,
              e.fit.kept.cross_validated_mm, e.fit.drift_rate);
  print_stats("held-out presses, position error", e.held_out);
  std::printf(
      "  their sigma (k sqrt(1 - explained + u0), k %.1f mm set on the calibration): mean %.2f mm; error within 1 "
      "sigma %.0f %%, 2 sigma %.0f %%\n",
      e.fit.response.error_scale_mm, e.held_out_sigma_mm, 100 * e.within_1sigma, 100 * e.within_2sigma);
  print_stats("always answering the presses' centre", e.held_out_centre);
  if (e.held_out_image) {
    const std::string what = "physics alone (NOSER image, " + std::to_string(e.image_triangles) + " triangles)";
    print_stats(what.c_str(), *e.held_out_image);
  }
  std::printf("  %.2f ms a frame\n", e.ms_per_frame);
  std::printf("  against calibration presses (held-out mean; cross-validated; response):\n");
  for (const RealCurvePoint& p : e.curve)
    std::printf("    %4ld presses: %6.2f mm   %6.2f mm   %s\n", static_cast<long>(p.calibration_presses),
                p.held_out.mean, p.kept.cross_validated_mm, response_name(p.kept).c_str());
  if (!job.contacts_path.empty())
    std::printf("  contacts: %s (presses %ld on)\n", job.contacts_path.c_str(),
                static_cast<long>(e.calibration_presses));
  if (!report.plot_path.empty()) std::printf("  plot: %s\n", report.plot_path.c_str());
}

}  // namespace emit::cli
