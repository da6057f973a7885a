// The board's wrapping microsecond clock unwrapped (acquire/board_clock.hpp). All values are
// whole microseconds, exact in a double, so the seconds are compared exactly (one product by 1e-6
// each side).
#include "emit/acquire/board_clock.hpp"

#include <cstdint>

#include <gtest/gtest.h>

namespace emit {
namespace {

TEST(BoardClock, FirstTimestampIsItsOwnValueThenForwardDifferencesAdd) {
  BoardClock clock;
  EXPECT_EQ(clock.seconds(7'000'000u), 7'000'000 * 1e-6);
  EXPECT_EQ(clock.seconds(7'020'000u), 7'020'000 * 1e-6);
  EXPECT_EQ(clock.seconds(7'040'000u), 7'040'000 * 1e-6);
}

// Across the 2^32 µs wrap: 20 ms before it, then 10 ms after it, is 30 ms later.
TEST(BoardClock, CarriesAcrossTheWrap) {
  BoardClock clock;
  const std::uint32_t before = 0xFFFFFFFFu - 19'999u;  // 2^32 − 20,000 µs
  const double start = clock.seconds(before);
  EXPECT_EQ(clock.seconds(10'000u), (4294967296.0 - 20'000 + 30'000) * 1e-6);
  EXPECT_EQ(start, (4294967296.0 - 20'000) * 1e-6);
}

// A step back (the board restarted): the clock stays where it was, then runs on from there.
TEST(BoardClock, AStepBackIsNoGap) {
  BoardClock clock;
  clock.seconds(600'000'000u);
  EXPECT_EQ(clock.seconds(1'000u), 600'000'000 * 1e-6);
  EXPECT_EQ(clock.seconds(21'000u), 600'020'000 * 1e-6);
}

}  // namespace
}  // namespace emit
