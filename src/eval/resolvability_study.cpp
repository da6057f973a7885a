#include "emit/eval/resolvability_study.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "emit/core/option_check.hpp"
#include "emit/eval/greit_merit.hpp"
#include "emit/sensor/surface.hpp"

namespace emit {

void ResolvabilityOptions::validate() const {
  const char* owner = "ResolvabilityOptions";
  for (double v : offsets_mm) option_check::non_negative(owner, "offsets_mm", v);
  for (double v : radii_mm) option_check::positive(owner, "radii_mm", v);
  for (double v : gaps_mm) option_check::positive(owner, "gaps_mm", v);
  if (!std::is_sorted(gaps_mm.begin(), gaps_mm.end()))
    option_check::fail(owner, "gaps_mm", "ascending", std::to_string(gaps_mm.size()) + " gaps out of order");
  for (double v : ring_inner_mm) option_check::within(owner, "ring_inner_mm", v, 0, ring_outer_mm);
  option_check::positive(owner, "force_N", force_N);
  option_check::positive(owner, "bar_width_mm", bar_width_mm);
  option_check::positive(owner, "bar_length_mm", bar_length_mm);
  option_check::positive(owner, "ring_outer_mm", ring_outer_mm);
  option_check::positive(owner, "pressure_N_per_mm2", pressure_N_per_mm2);
  option_check::non_negative(owner, "clearance_mm", clearance_mm);
  option_check::at_least(owner, "reference_frames", reference_frames, 1);
}

ResolvabilityOptions quick_resolvability_options() {
  ResolvabilityOptions o;
  o.offsets_mm = {0, 16};
  o.radii_mm = {3};
  o.gaps_mm = {4};
  o.ring_inner_mm = {6};
  return o;
}

ResolvabilityStudy study_resolvability(const Sensor& sensor, const FitModel& fit, const ResolvabilityOptions& options,
                                       const Progress& progress) {
  options.validate();
  const MeasurementSet measurements = make_measurement_set(sensor.electrode_count());
  Resolvability r(sensor, fit, measurements, options.reference_frames);
  ResolvabilityStudy s;
  s.centre_mm = sheet_centre_mm(fit.mesh);
  s.noise_V = r.noise_V();
  s.offsets_mm = options.offsets_mm, s.radii_mm = options.radii_mm, s.gaps_mm = options.gaps_mm;
  s.ring_inner_mm = options.ring_inner_mm;
  const Border& border = sheet_outline(sensor);
  // A region of half-extents (hx, hy) about c fits when its box's corners and sides' middles are
  // clearance_mm inside the border.
  const auto fits = [&](const Vector2& c, double hx, double hy) {
    for (int i = -1; i <= 1; ++i)
      for (int j = -1; j <= 1; ++j) {
        const Vector2 p = c + Vector2(i * hx, j * hy);
        if (!border.contains(p) || border.distance_to_border_mm(p) < options.clearance_mm) return false;
      }
    return true;
  };
  const auto place = [&](double offset) -> Vector2 { return s.centre_mm + Vector2(offset, 0); };

  progress.say("  round presses: the Cramér–Rao bound");
  for (double radius : options.radii_mm) {
    std::vector<RoundContactBound> row;
    for (double offset : options.offsets_mm) {
      if (!fits(place(offset), radius / std::sqrt(2.0), radius / std::sqrt(2.0)) || !fits(place(offset), radius, 0)) {
        row.push_back({NAN, NAN, NAN, NAN, NAN, NAN, NAN});
        continue;
      }
      row.push_back(r.round_contact_bound(place(offset), radius, options.force_N));
    }
    s.round.push_back(row);
  }

  const auto smallest_resolved = [&](const std::vector<std::vector<double>>& delta_chi2) {
    std::vector<double> gaps;
    for (std::size_t o = 0; o < options.offsets_mm.size(); ++o) {
      double smallest = NAN;
      for (std::size_t g = options.gaps_mm.size(); g-- > 0;) {
        if (!(delta_chi2[g][o] >= Resolvability::resolved_delta_chi2)) break;
        smallest = options.gaps_mm[g];
      }
      gaps.push_back(smallest);
    }
    return gaps;
  };
  for (const bool held : {false, true}) {
    progress.say(held ? "  two bars against one at their pressure" : "  two bars against one");
    auto& table = held ? s.gap_delta_chi2_held : s.gap_delta_chi2;
    for (double gap : options.gaps_mm) {
      std::vector<double> row;
      for (double offset : options.offsets_mm) {
        const double half_x = options.bar_width_mm + gap / 2;
        row.push_back(fits(place(offset), half_x, options.bar_length_mm / 2)
                          ? r.two_bars_against_one(place(offset), options.bar_width_mm, options.bar_length_mm, gap,
                                                   options.pressure_N_per_mm2, held)
                                .delta_chi2
                          : NAN);
      }
      table.push_back(row);
    }
    (held ? s.resolvable_gap_held_mm : s.resolvable_gap_mm) = smallest_resolved(table);

    progress.say(held ? "  rings against discs at their pressure" : "  rings against discs");
    auto& rings = held ? s.ring_delta_chi2_held : s.ring_delta_chi2;
    const double diagonal = options.ring_outer_mm / std::sqrt(2.0);
    for (double inner : options.ring_inner_mm) {
      std::vector<double> row;
      for (double offset : options.offsets_mm)
        row.push_back(
            fits(place(offset), diagonal, diagonal) && fits(place(offset), options.ring_outer_mm, 0)
                ? r.ring_against_disc(place(offset), inner, options.ring_outer_mm, options.pressure_N_per_mm2, held)
                      .delta_chi2
                : NAN);
      rings.push_back(row);
    }
  }
  return s;
}

}  // namespace emit
