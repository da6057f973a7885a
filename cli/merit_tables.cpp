// `emit eval --figures-of-merit`'s table (GREIT's figures per method: mean ± spread over the
// places, AR's coefficient of variation) and `emit eval --resolvability`'s (what a frame can
// tell, against the place on the sheet).
#include <cmath>
#include <cstdio>
#include <string>

#include "commands.hpp"
#include "emit/jobs/merit_eval_job.hpp"

namespace emit::cli {

void print_figures_of_merit(const FiguresOfMeritOptions& options, const MeritEvalReport& report) {
  const FiguresOfMerit& f = report.merit;
  std::printf("  %d places, presses r %.1f mm, %.1f N; reconstruction mesh %ld triangles\n", f.places,
              options.radius_mm, options.force_N, f.triangles);
  std::printf("  %-14s %-18s %6s  %-16s %-16s %-16s %-16s %s\n", "method", "AR (mean)", "AR CV", "PE mm", "RES", "SD",
              "RNG", "blank");
  for (const MethodMerit& m : f.methods) {
    const char* unit = m.pressure ? "N/N" : "V.mm2/N";
    const std::string name =
        std::string(method_name(m.method)) + (is_linear(m.method) ? (m.pressure ? "-P" : "-dphi") : "");
    std::printf(
        "  %-14s %10.4g %-7s %5.1f %%  %+6.2f +/- %5.2f  %6.3f +/- %5.3f  %6.3f +/- %5.3f  %6.3f +/- %5.3f  %d\n",
        name.c_str(), m.amplitude_response.mean, unit, 100 * m.amplitude_response_cv, m.position_error_mm.mean,
        m.position_error_mm.std, m.resolution.mean, m.resolution.std, m.shape_deformation.mean, m.shape_deformation.std,
        m.ringing.mean, m.ringing.std, m.blank);
  }
  for (const std::string& path : report.plots) std::printf("  wrote %s\n", path.c_str());
}

namespace {

void print_offsets_header(const ResolvabilityStudy& s, const char* first) {
  std::printf("    %-18s", first);
  for (double offset : s.offsets_mm) std::printf("  %7.0f mm", offset);
  std::printf("\n");
}

void print_value(double value, const char* format) {
  if (std::isnan(value)) std::printf("  %10s", "-");
  else std::printf(format, value);
}

}  // namespace

void print_resolvability(const ResolvabilityOptions& options, const ResolvabilityStudy& s) {
  std::printf("  places: the sheet's centre (%.1f, %.1f) mm, then along +x by the offsets; noise of delta V %.3g mV\n",
              s.centre_mm.x(), s.centre_mm.y(), 1e3 * s.noise_V);
  std::printf("  (i) a round flat press of %.1f N: Cramer-Rao 1 sigma of radius (mm) / centre x (mm) / force (%%)\n",
              options.force_N);
  print_offsets_header(s, "radius \\ offset");
  for (std::size_t i = 0; i < s.radii_mm.size(); ++i) {
    std::printf("    r %5.1f mm        ", s.radii_mm[i]);
    for (const RoundContactBound& b : s.round[i])
      if (std::isnan(b.radius_std_mm)) std::printf("  %10s", "-");
      else std::printf("  %5.2g/%.2g/%.2g", b.radius_std_mm, b.x_std_mm, 100 * b.log_force_std);
    std::printf("\n");
  }
  for (const bool held : {false, true}) {
    std::printf("  (ii%s) two parallel bars %.0f x %.0f mm at %.2f N/mm2 against the best single bar%s: delta chi2\n",
                held ? "b" : "", options.bar_width_mm, options.bar_length_mm, options.pressure_N_per_mm2,
                held ? " at their pressure" : "");
    print_offsets_header(s, "gap \\ offset");
    const auto& gaps = held ? s.gap_delta_chi2_held : s.gap_delta_chi2;
    for (std::size_t g = 0; g < s.gaps_mm.size(); ++g) {
      std::printf("    gap %5.1f mm      ", s.gaps_mm[g]);
      for (double v : gaps[g]) print_value(v, "  %10.3g");
      std::printf("\n");
    }
    std::printf("    resolved (>= %.0f) ", Resolvability::resolved_delta_chi2);
    for (double v : held ? s.resolvable_gap_held_mm : s.resolvable_gap_mm) print_value(v, "  %7.1f mm");
    std::printf("\n");
  }
  for (const bool held : {false, true}) {
    std::printf("  (iii%s) a ring of outer radius %.0f mm at %.2f N/mm2 against the best full disc%s: delta chi2\n",
                held ? "b" : "", options.ring_outer_mm, options.pressure_N_per_mm2, held ? " at its pressure" : "");
    print_offsets_header(s, "hole r \\ offset");
    const auto& rings = held ? s.ring_delta_chi2_held : s.ring_delta_chi2;
    for (std::size_t h = 0; h < s.ring_inner_mm.size(); ++h) {
      std::printf("    hole r %4.1f mm   ", s.ring_inner_mm[h]);
      for (double v : rings[h]) print_value(v, "  %10.3g");
      std::printf("\n");
    }
  }
  std::printf("  delta chi2 >= %.0f: one frame tells the two apart (2.3 %% error either way); n frames: n times it\n",
              Resolvability::resolved_delta_chi2);
}

}  // namespace emit::cli
