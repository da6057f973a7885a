#include "emit/live/latency_stats.hpp"

#include <algorithm>
#include <cmath>

namespace emit {

LatencyStats::LatencyStats() : bins_(static_cast<std::size_t>(std::ceil(range_s / bin_s)), 0) {}

void LatencyStats::add(double seconds) {
  seconds = std::max(seconds, 0.0);
  const auto bin = std::min(static_cast<std::size_t>(seconds / bin_s), bins_.size() - 1);
  ++bins_[bin];
  ++count_;
  sum_s_ += seconds;
  max_s_ = std::max(max_s_, seconds);
}

double LatencyStats::quantile_s(double q) const {
  if (count_ == 0) return 0;
  const auto rank = static_cast<std::uint64_t>(std::ceil(std::clamp(q, 0.0, 1.0) * static_cast<double>(count_)));
  std::uint64_t seen = 0;
  for (std::size_t b = 0; b < bins_.size(); ++b) {
    seen += bins_[b];
    // The last bin holds every latency beyond range_s: its upper edge is the largest one seen.
    if (seen >= std::max<std::uint64_t>(rank, 1))
      return b + 1 == bins_.size() ? max_s_ : std::min(static_cast<double>(b + 1) * bin_s, max_s_);
  }
  return max_s_;
}

}  // namespace emit
