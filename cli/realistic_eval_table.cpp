// The table `emit eval --realistic` prints: each figure of the realistic round, with the nominal
// file and after the sensor's calibration, beside its target (eval/realistic_evaluation.hpp).
#include <cstdio>
#include <string>

#include "commands.hpp"
#include "emit/eval/realistic_evaluation.hpp"

namespace emit::cli {

namespace {

/// A figure of the realistic round beside its target: the nominal file's, the calibrated one's.
void print_row(const char* figure, const std::string& nominal, const std::string& calibrated, const std::string& target,
               bool met) {
  std::printf("  %-52s %-14s %-20s %-14s %s\n", figure, nominal.c_str(), calibrated.c_str(), target.c_str(),
              target.empty() ? "" : (met ? "met" : "MISSED"));
}

std::string format(const char* pattern, double value) {
  char text[64];
  std::snprintf(text, sizeof text, pattern, value);
  return text;
}

std::string percent(double fraction) { return format("%.1f %%", 100 * fraction); }

std::string of_frames(double fraction, int frames) {
  return format("%.0f %%", 100 * fraction) + " of " + std::to_string(frames);
}

}  // namespace

void print_realistic_evaluation(const RealisticEvaluation& e) {
  using T = RealisticTargets;
  const SinglePressScore &n = e.nominal, &c = e.calibrated, &o = e.other_indenters;
  const RealisticEvalCounts& k = e.counts;
  std::printf(
      "  %d reference frames, %d calibration and %d test presses (r = %.1f mm, flat); reconstruction mesh "
      "%ld triangles\n",
      k.reference_frames, k.calibration_presses, k.test_presses, e.radius_mm, e.triangles);
  if (k.calibration_iterations > 0)
    std::printf("  the sensor calibration stopped after at most %d iterations\n", k.calibration_iterations);
  const bool field = e.unplaced_known_forces > 0;
  if (field)
    std::printf("  calibrated as in the field: every calibration press's place unknown, %d of known force\n",
                e.unplaced_known_forces);
  const double mean_mm = field ? UnplacedTargets::position_mean_mm : T::position_mean_mm;
  const double p95_mm = field ? UnplacedTargets::position_p95_mm : T::position_p95_mm;
  const double pressure = field ? UnplacedTargets::pressure_error_N_per_mm2 : T::pressure_error_N_per_mm2;
  std::printf("  %-52s %-14s %-20s %-14s\n", "contact fitting", "nominal file", "calibrated", "target");
  print_row("position, mean", format("%.3f mm", n.position_mm.mean), format("%.3f mm", c.position_mm.mean),
            format("<= %.1f mm", mean_mm), c.position_mm.mean <= mean_mm);
  print_row("position, p95", format("%.3f mm", n.position_mm.p95), format("%.3f mm", c.position_mm.p95),
            format("<= %.1f mm", p95_mm), c.position_mm.p95 <= p95_mm);
  print_row("presses without a contact", std::to_string(n.position_mm.missed), std::to_string(c.position_mm.missed), "",
            true);
  print_row("force, mean |relative error| (same indenter)", percent(n.force_error), percent(c.force_error),
            format("<= %.0f %%", 100 * T::force_error), c.force_error <= T::force_error);
  print_row("pressure, mean |error| (N/mm2)", format("%.4f", n.pressure_error_N_per_mm2),
            format("%.4f", c.pressure_error_N_per_mm2), format("<= %.2f", pressure),
            c.pressure_error_N_per_mm2 <= pressure);
  const double false_rate = e.single_presses ? e.false_contacts / static_cast<double>(e.single_presses) : 0;
  print_row("false contacts (single presses, > 1 contact)",
            std::to_string(n.extra_contacts) + " of " + std::to_string(n.frames),
            std::to_string(e.false_contacts) + " of " + std::to_string(e.single_presses),
            format("<= %.0f %%", 100 * T::false_contacts), false_rate <= T::false_contacts);
  char others[96] = "other indenters, mean |force error|";
  if (!e.indenters.empty())
    std::snprintf(others, sizeof others, "other indenters (%g-%g mm), mean |force error|",
                  e.indenters.front().radius_mm, e.indenters.back().radius_mm);
  print_row(others, "-", percent(o.force_error), format("<= %.0f %%", 100 * T::other_indenters_force_error),
            o.force_error <= T::other_indenters_force_error);
  print_row("  |force error| within the reported 1 sigma", "-", percent(o.within_1_sigma),
            format(">= %.0f %%", 100 * T::within_1_sigma), o.within_1_sigma >= T::within_1_sigma);
  print_row("  |force error| within 2 sigma", "-", percent(o.within_2_sigma),
            format(">= %.0f %%", 100 * T::within_2_sigma), o.within_2_sigma >= T::within_2_sigma);
  const std::string apart = format("%.0f mm apart", e.separation_mm);
  const std::string within = format("within %.0f mm", e.match_mm);
  print_row(("three presses >= " + apart + ", all " + within).c_str(), "-",
            of_frames(e.three_presses, k.multi_press_frames), format(">= %.0f %%", 100 * T::three_presses),
            e.three_presses >= T::three_presses);
  print_row(("four presses >= " + apart + ", all " + within).c_str(), "-",
            of_frames(e.four_presses, k.multi_press_frames), format(">= %.0f %%", 100 * T::four_presses),
            e.four_presses >= T::four_presses);
  const ParameterCoverage& sp = e.sheet_parameters;
  if (sp.parameters > 0)
    print_row("sheet parameters within their 2 sigma of the truth", "-",
              std::to_string(sp.within_2_sigma) + " of " + std::to_string(sp.parameters) + " (1 sigma " +
                  std::to_string(sp.within_1_sigma) + ")",
              format(">= %.0f %%", 100 * T::parameters_within_2_sigma),
              sp.within_2_sigma >= T::parameters_within_2_sigma * sp.parameters);
  print_row("calibration, wall time", "-", format("%.1f s", e.calibration_s), format("<= %.0f s", T::calibration_s),
            e.calibration_s <= T::calibration_s);
  print_row("contact fitting, a frame of one press", "-", format("%.1f ms", e.fit_ms_per_frame), "", true);
  print_row("  of three or four presses", "-", format("%.0f ms", e.several_ms_per_frame), "", true);
  std::printf("  other indenters, mean force error (%d presses each):", k.presses_per_indenter);
  for (const IndenterScore& i : e.indenters)
    std::printf(" %s %.1f mm %+.1f %%%s", profile_name(i.profile), i.radius_mm, 100 * i.score.force_bias,
                &i == &e.indenters.back() ? "\n" : ",");
  const SinglePressScore &p = e.paper, &po = e.paper_other_indenters, &p8 = e.paper_equation_8;
  std::printf(
      "  paper method after emit calibrate --method paper (force from the image's integral): force %.1f %% "
      "mean |error| (bias %+.1f %%), pressure %.4f N/mm2, position %.2f mm; other indenters: force %.1f %% "
      "(within 1 sigma %.0f %%, 2 sigma %.0f %%); eq. 8 summed over the 50 %% region: force %.1f %% (x%.2f)\n",
      100 * p.force_error, 100 * p.force_bias, p.pressure_error_N_per_mm2, p.position_mm.mean, 100 * po.force_error,
      100 * po.within_1_sigma, 100 * po.within_2_sigma, 100 * p8.force_error, 1 + p8.force_bias);
  for (const std::string& w : e.calibration_warnings)
    std::fprintf(stderr, "emit: warning: calibration: %s\n", w.c_str());
}

}  // namespace emit::cli
