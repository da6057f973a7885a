#include "border_breakpoints.hpp"

#include <algorithm>

namespace emit::detail {

std::vector<Breakpoint> border_breakpoints(const Border& border, const std::vector<Electrode>& electrodes) {
  std::vector<Breakpoint> points;
  for (const auto& piece : border.pieces()) points.push_back({piece.start_s_mm, false});
  for (const auto& e : electrodes) {
    points.push_back({wrap_arclength(e.center_s_mm - 0.5 * e.width_mm, border.length_mm()), true});
    points.push_back({wrap_arclength(e.center_s_mm + 0.5 * e.width_mm, border.length_mm()), true});
  }
  std::sort(points.begin(), points.end(), [](const auto& a, const auto& b) { return a.s_mm < b.s_mm; });
  // Merge points closer than a tiny fraction of the border (an electrode ending on a corner).
  const double merge_mm = 1e-9 * border.length_mm();
  std::vector<Breakpoint> merged;
  for (const auto& p : points) {
    if (!merged.empty() && p.s_mm - merged.back().s_mm <= merge_mm) {
      merged.back().electrode_end = merged.back().electrode_end || p.electrode_end;
      continue;
    }
    merged.push_back(p);
  }
  if (merged.size() > 1 && merged.front().s_mm + border.length_mm() - merged.back().s_mm <= merge_mm) {
    merged.front().electrode_end = merged.front().electrode_end || merged.back().electrode_end;
    merged.pop_back();
  }
  return merged;
}

}  // namespace emit::detail
