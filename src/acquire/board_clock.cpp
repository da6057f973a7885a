#include "emit/acquire/board_clock.hpp"

namespace emit {

double BoardClock::seconds(std::uint32_t timestamp_us) {
  if (!started_) {
    started_ = true;
    total_us_ = timestamp_us;
  } else {
    const std::uint32_t forward_us = timestamp_us - last_us_;  // modulo 2^32: across a wrap too
    if (forward_us < (1u << 31)) total_us_ += forward_us;      // else: a step back, no gap
  }
  last_us_ = timestamp_us;
  return static_cast<double>(total_us_) * 1e-6;
}

}  // namespace emit
