#include "emit/acquire/electrode_health.hpp"

#include <algorithm>
#include <cstdio>

#include "emit/core/errors.hpp"
#include "emit/sensor/adc.hpp"

namespace emit {

namespace {

/// What "stuck at a rail" allows: the ADC's noise (5 σ) or two steps, whichever is larger.
double rail_tolerance_V(const AdcSpec& adc) { return std::max(2 * adc_step_V(adc), 5 * adc.noise_V); }

/// A frame says something about the electrodes only if a press raised some reading well clear
/// of the rail tolerance.
bool has_signal(const Frame& frame, double tolerance) { return frame.maxCoeff() > 20 * tolerance; }

bool column_at_zero(const Frame& frame, Index m, double step) {
  for (Index l = 0; l < frame.rows(); ++l)
    if (l != m && frame(l, m) > step) return false;
  return true;
}

bool row_at_full_scale(const Frame& frame, Index l, const AdcSpec& adc, double step) {
  for (Index m = 0; m < frame.cols(); ++m)
    if (m != l && frame(l, m) < adc.vref_V - step) return false;
  return true;
}

}  // namespace

std::vector<DeadElectrode> find_dead_electrodes(const std::vector<Frame>& frames, const AdcSpec& adc) {
  const double step = rail_tolerance_V(adc);
  std::vector<DeadElectrode> dead;
  if (frames.empty()) return dead;
  const Index N = frames[0].rows();
  int with_signal = 0;
  std::vector<int> zero_columns(static_cast<std::size_t>(N), 0), full_rows(static_cast<std::size_t>(N), 0);
  for (const Frame& frame : frames) {
    if (!has_signal(frame, step)) continue;
    ++with_signal;
    for (Index e = 0; e < N; ++e) {
      zero_columns[e] += column_at_zero(frame, e, step);
      full_rows[e] += row_at_full_scale(frame, e, adc, step);
    }
  }
  if (with_signal == 0) return dead;
  const std::string in_all = " in all " + std::to_string(with_signal) + " frames with signal";
  for (Index e = 0; e < N; ++e) {
    if (zero_columns[e] == with_signal)
      dead.push_back({static_cast<int>(e), "reads 0 V as the sensed electrode" + in_all});
    else if (full_rows[e] == with_signal)
      dead.push_back({static_cast<int>(e), "grounds nothing (its row reads full scale)" + in_all});
  }
  return dead;
}

void check_no_stuck_rows(const std::vector<Frame>& frames, const AdcSpec& adc, const std::vector<int>& dead,
                         const std::string& source) {
  const double step = rail_tolerance_V(adc);
  for (std::size_t f = 0; f < frames.size(); ++f)
    for (Index l = 0; l < frames[f].rows(); ++l) {
      if (std::find(dead.begin(), dead.end(), static_cast<int>(l)) != dead.end()) continue;
      if (has_signal(frames[f], step) && row_at_full_scale(frames[f], l, adc, step)) {
        char value[32];
        std::snprintf(value, sizeof value, "%.4g", frames[f](l, l == 0 ? 1 : 0));
        throw InvalidInput(source + ": frame " + std::to_string(f) + ": ground " + std::to_string(l) + " reads " +
                           value + " V (full scale) on every electrode: was electrode " + std::to_string(l) +
                           " grounded?");
      }
    }
}

}  // namespace emit
