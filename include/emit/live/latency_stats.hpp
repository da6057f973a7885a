#pragma once
/// \file latency_stats.hpp
/// Mean and percentiles of many durations without storing them: a histogram of fixed 50 µs bins
/// up to 2 s (the percentiles' resolution), sized once, so adding allocates nothing.
#include <cstdint>
#include <vector>

namespace emit {

class LatencyStats {
 public:
  static constexpr double bin_s = 50e-6;
  static constexpr double range_s = 2.0;  ///< longer latencies count in the last bin (and in max_s)

  LatencyStats();
  void add(double seconds);
  std::uint64_t count() const { return count_; }
  double mean_s() const { return count_ ? sum_s_ / static_cast<double>(count_) : 0; }
  double max_s() const { return max_s_; }
  /// The q-quantile (q in [0, 1]) to within bin_s: the upper edge of the bin holding it; 0 if empty.
  /// Beyond range_s, an upper bound: the largest latency seen.
  double quantile_s(double q) const;

 private:
  std::vector<std::uint64_t> bins_;
  std::uint64_t count_ = 0;
  double sum_s_ = 0, max_s_ = 0;
};

}  // namespace emit
