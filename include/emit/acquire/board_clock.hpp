#pragma once
/// \file board_clock.hpp
/// The board's 32-bit microsecond timestamps (packet v1; they wrap every 2^32 µs ≈ 71.6 min)
/// unwrapped into seconds on a clock that does not wrap.
///
/// Consecutive frames are milliseconds apart, so the forward difference modulo 2^32 is the elapsed
/// time. A difference of 2^31 µs (≈ 36 min) or more is taken for a step backwards (the board
/// restarted, its clock from 0 again): the unwrapped time then stays where it was, no gap. The
/// same rule carries the clock across a reconnect: a board that kept running gives the true gap,
/// one that restarted gives none.
#include <cstdint>

namespace emit {

class BoardClock {
 public:
  /// Seconds on the unwrapped clock for the next timestamp. The first one is its own value,
  /// timestamp_us · 1e-6; later ones add the forward difference.
  double seconds(std::uint32_t timestamp_us);

 private:
  bool started_ = false;
  std::uint32_t last_us_ = 0;
  std::uint64_t total_us_ = 0;  ///< unwrapped time of last_us_
};

}  // namespace emit
