#include "emit/acquire/electrode_health.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "emit/acquire/electrode_swap.hpp"
#include "emit/core/errors.hpp"
#include "emit/sensor/adc.hpp"

namespace emit {

namespace {

/// What "stuck at a rail" allows: the ADC's noise (5 σ) or two steps, whichever is larger.
double rail_tolerance_V(const AdcSpec& adc) { return std::max(2 * adc_step_V(adc), 5 * adc.noise_V); }

/// No swap is looked for with so few electrodes: no border to speak of.
constexpr Index min_swap_electrodes = 4;

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

ElectrodeHealthTally::ElectrodeHealthTally(int electrode_count, const AdcSpec& adc)
    : adc_(adc),
      tolerance_V_(rail_tolerance_V(adc)),
      zero_columns_(static_cast<std::size_t>(electrode_count), 0),
      full_rows_(static_cast<std::size_t>(electrode_count), 0),
      swap_votes_(static_cast<std::size_t>(electrode_count) * static_cast<std::size_t>(electrode_count), 0) {}

void ElectrodeHealthTally::add(const Frame& frame) {
  if (!frame.allFinite() || !has_signal(frame, tolerance_V_)) return;  // a frame with a masked reading says less
  ++with_signal_;
  for (Index e = 0; e < frame.rows(); ++e) {
    zero_columns_[static_cast<std::size_t>(e)] += column_at_zero(frame, e, tolerance_V_);
    full_rows_[static_cast<std::size_t>(e)] += row_at_full_scale(frame, e, adc_, tolerance_V_);
  }
  if (frame.rows() <= min_swap_electrodes) return;
  const SwapCandidate swap = best_swap(frame);
  if (swap.a >= 0 && swap.roughness_ratio < swap_roughness_ratio)
    ++swap_votes_[static_cast<std::size_t>(swap.a) * static_cast<std::size_t>(frame.rows()) +
                  static_cast<std::size_t>(swap.b)];
}

void ElectrodeHealthTally::reset() {
  with_signal_ = 0;
  std::fill(zero_columns_.begin(), zero_columns_.end(), 0);
  std::fill(full_rows_.begin(), full_rows_.end(), 0);
  std::fill(swap_votes_.begin(), swap_votes_.end(), 0);
}

std::vector<SwappedElectrodes> ElectrodeHealthTally::swapped() const {
  std::vector<SwappedElectrodes> swapped;
  if (with_signal_ < min_swap_frames || !dead().empty()) return swapped;
  const std::size_t n = zero_columns_.size();
  for (std::size_t a = 0; a < n; ++a)
    for (std::size_t b = a + 1; b < n; ++b) {
      const int votes = swap_votes_[a * n + b];
      if (votes >= swap_vote_fraction * with_signal_)
        swapped.push_back({static_cast<int>(a), static_cast<int>(b),
                           "their readings fit each other's places along the border in " + std::to_string(votes) +
                               " of " + std::to_string(with_signal_) + " frames with signal"});
    }
  return swapped;
}

std::vector<DeadElectrode> ElectrodeHealthTally::dead() const {
  std::vector<DeadElectrode> dead;
  if (with_signal_ == 0) return dead;
  const std::string in_all = " in all " + std::to_string(with_signal_) + " frames with signal";
  for (std::size_t e = 0; e < zero_columns_.size(); ++e) {
    if (zero_columns_[e] == with_signal_)
      dead.push_back({static_cast<int>(e), "reads 0 V as the sensed electrode" + in_all});
    else if (full_rows_[e] == with_signal_)
      dead.push_back({static_cast<int>(e), "grounds nothing (its row reads full scale)" + in_all});
  }
  return dead;
}

std::vector<DeadElectrode> find_dead_electrodes(const std::vector<Frame>& frames, const AdcSpec& adc) {
  if (frames.empty()) return {};
  ElectrodeHealthTally tally(static_cast<int>(frames[0].rows()), adc);
  for (const Frame& frame : frames) tally.add(frame);
  return tally.dead();
}

std::string reading_out_of_range(const Eigen::Ref<const Frame>& frame, const AdcSpec& adc) {
  const double tolerance = rail_tolerance_V(adc);
  for (Index l = 0; l < frame.rows(); ++l)
    for (Index m = 0; m < frame.cols(); ++m) {
      const double v = frame(l, m);
      if (!std::isfinite(v) || (v >= -tolerance && v <= adc.vref_V + tolerance)) continue;  // NaN: masked
      char text[160];
      std::snprintf(text, sizeof text,
                    "ground %lld, sense %lld reads %.4g V, outside the ADC's 0 to %.4g V (sensor \"adc\")",
                    static_cast<long long>(l), static_cast<long long>(m), v, adc.vref_V);
      return text;
    }
  return {};
}

void check_readings_in_range(const Eigen::Ref<const Frame>& frame, const AdcSpec& adc, const std::string& where) {
  if (std::string problem = reading_out_of_range(frame, adc); !problem.empty())
    throw InvalidInput(where + ": " + problem);
}

bool looks_pressed(const Frame& frame, const AdcSpec& adc) { return has_signal(frame, rail_tolerance_V(adc)); }

}  // namespace emit
