// The table `emit eval --outlines` prints: per method, each outline family's pressed-region scores
// (eval/outline_evaluation.hpp).
#include <cmath>
#include <cstdio>
#include <string>

#include "commands.hpp"
#include "emit/eval/outline_evaluation.hpp"

namespace emit::cli {

namespace {

std::string or_dash(const char* pattern, double value) {
  if (!std::isfinite(value)) return "-";
  char text[64];
  std::snprintf(text, sizeof text, pattern, value);
  return text;
}

/// "68/95 %": the fractions within 1σ and 2σ, or "-" for a method that reports no σ.
std::string coverage(double within_1, double within_2) {
  if (!std::isfinite(within_1) || !std::isfinite(within_2)) return "-";
  char text[32];
  std::snprintf(text, sizeof text, "%.0f/%.0f %%", 100 * within_1, 100 * within_2);
  return text;
}

void print_family(const OutlineFamilyScore& s) {
  std::printf("  %-15s %6d %6.2f %9.1f %% %8s %10s %10s %8.2f %7.0f %% %7s %11s %11s\n", s.family.c_str(), s.frames,
              s.dice, 100 * s.force_error, or_dash("x%.2f", s.force_ratio).c_str(),
              or_dash("%.2f mm", s.centroid_mm).c_str(), or_dash("%.1f deg", s.orientation_deg).c_str(), s.regions,
              100 * s.right_count, or_dash("x%.2f", s.area_ratio).c_str(),
              coverage(s.area_within_1sigma, s.area_within_2sigma).c_str(),
              coverage(s.force_within_1sigma, s.force_within_2sigma).c_str());
}

}  // namespace

void print_outline_evaluation(const OutlineEvaluation& e) {
  std::printf(
      "  each method calibrated on %d disc presses (r 5 mm, 2-39 N) as emit calibrate does; reconstruction mesh %ld "
      "triangles\n"
      "  Dice: 2|A&B|/(|A|+|B|) of the pressed region (pressure > 0) and the outline, area-weighted on the\n"
      "  reconstruction's triangles; force: the contacts' sum against the true; centroid: the region's;\n"
      "  orientation: the region's principal axis (elongated outlines); regions: contacts reported;\n"
      "  area: the contacts' against the true; A in 1/2 sigma, F in 1/2 sigma: the fractions of frames whose\n"
      "  true area, force is within the reported 1 and 2 sigma (of the log: |ln(reported/true)| <= k sigma/reported;\n"
      "  - where the method reports none)%s\n",
      e.calibration_presses, e.triangles,
      e.indenters ? "\n  flat discs of each radius after calibration with 5 mm ones; 'declared': --contact-radius-mm "
                    "given as each disc's radius"
                  : "");
  for (const MethodOutlineScore& m : e.methods) {
    std::printf("\n  %s%s (calibration rms %.4f N/mm2 on its presses; %.0f ms a frame)\n", method_name(m.method),
                m.declared_radius ? ", declared" : "", m.calibration_rms_N_per_mm2, m.ms_per_frame);
    std::printf("  %-15s %6s %6s %11s %8s %10s %10s %8s %9s %7s %11s %11s\n", e.indenters ? "indenter" : "outline",
                "frames", "Dice", "|force err|", "force", "centroid", "orient.", "regions", "right n", "area",
                "A in 1/2 s", "F in 1/2 s");
    for (const OutlineFamilyScore& s : m.families) print_family(s);
    print_family(m.all);
    if (m.all.frames_without_region > 0)
      std::printf("  %d frames without a region (their centroid not averaged; orientation counted 90 deg)\n",
                  m.all.frames_without_region);
  }
}

}  // namespace emit::cli
