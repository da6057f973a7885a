// Two electrodes wired in each other's places, told from the frames' shape along the border
// (acquire/electrode_swap.hpp): on the twin's frames and on the independent implementation's
// (tests/data/conformance), unswapped frames name no exchange and a swapped pair is named.
#include "emit/acquire/electrode_swap.hpp"

#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "emit/acquire/electrode_health.hpp"
#include "emit/io/frames_csv.hpp"
#include "emit/sensor/sensor_json.hpp"
#include "emit/twin/twin.hpp"
#include "test_support.hpp"

namespace emit {
namespace {

/// The frame as read when electrodes a and b are wired in each other's places.
Frame swapped(const Frame& frame, int a, int b) {
  Frame out = frame;
  out.row(a).swap(out.row(b));
  out.col(a).swap(out.col(b));
  return out;
}

/// Pairs to swap: neighbours along the border (0, 1), across the square's corners (3, 4) and
/// (7, 8); apart along it, and across the sheet.
const std::vector<std::pair<int, int>> pairs = {{7, 8}, {3, 4}, {0, 1}, {2, 10}, {5, 12}, {1, 14}, {4, 6}};
bool adjacent(int a, int b) { return b - a == 1 || (a == 0 && b == 15); }

/// Each pair swapped in every frame: a pair apart along the border is the best exchange of every
/// frame, below swap_roughness_ratio; a neighbouring one of a swap_vote_fraction of the frames at
/// least (the tally's rule: a press on a corner's diagonal reads alike from either side of it).
/// And no frame as read has an exchange below the ratio.
void expect_swaps_named(const std::vector<Frame>& frames, const std::string& what) {
  for (std::size_t k = 0; k < frames.size(); ++k)
    EXPECT_GE(best_swap(frames[k]).roughness_ratio, swap_roughness_ratio) << what << " frame " << k << " as read";
  for (const auto& [a, b] : pairs) {
    int named = 0;
    for (const Frame& frame : frames) {
      const SwapCandidate found = best_swap(swapped(frame, a, b));
      named += found.a == a && found.b == b && found.roughness_ratio < swap_roughness_ratio;
    }
    const auto all = static_cast<int>(frames.size());
    if (adjacent(a, b)) EXPECT_GE(named, swap_vote_fraction * all) << what << ": " << a << " and " << b;
    else EXPECT_EQ(named, all) << what << ": " << a << " and " << b;
  }
}

// The twin's frames of single presses over the default sheet (one on a corner's diagonal).
TEST(ElectrodeSwap, TheTwinsFramesNameNoSwapAndASwappedPairIsNamed) {
  const Sensor sensor = default_sensor();
  Twin twin(sensor);
  std::vector<Frame> frames;
  for (const auto& [x, y, f] :
       std::vector<std::array<double, 3>>{{30, 30, 10}, {12, 45, 4}, {50, 10, 20}, {20, 15, 8}, {44, 38, 6}})
    frames.push_back(twin.frame({{x, y, 5, f}}));
  expect_swaps_named(frames, "twin");
}

class ElectrodeSwapConformance : public ::testing::TestWithParam<const char*> {};

// The independent implementation's exact frames (square: 5 presses, circle: 2, dome: 3): the same.
TEST_P(ElectrodeSwapConformance, IndependentFramesNameNoSwapAndASwappedPairIsNamed) {
  const std::string base = test::source_path(std::string("tests/data/conformance/") + GetParam());
  const auto frames = read_frames_csv(base + "_frames.csv", 16);
  ASSERT_FALSE(frames.empty());
  expect_swaps_named(frames, GetParam());
}

INSTANTIATE_TEST_SUITE_P(Sheets, ElectrodeSwapConformance, ::testing::Values("square60", "circle40", "dome25"));

// Over frames with signal the tally names the pair with why; a healthy run names none, and a
// dead electrode (its zero column is no border's shape) none either.
TEST(ElectrodeSwap, TheTallyNamesASwappedPairOverFramesWithSignal) {
  const Sensor sensor = default_sensor();
  Twin twin(sensor);
  ElectrodeHealthTally healthy(16, sensor.adc), crossed(16, sensor.adc), dead(16, sensor.adc);
  for (int k = 0; k < 6; ++k) {
    const Frame frame = twin.frame({{12.0 + 7 * k, 20.0 + 4 * k, 5, 6}});
    healthy.add(frame);
    crossed.add(swapped(frame, 4, 11));
    Frame without = swapped(frame, 4, 11);
    without.col(2).setZero();  // electrode 2 reads nothing
    dead.add(without);
  }
  EXPECT_TRUE(healthy.swapped().empty());
  const auto named = crossed.swapped();
  ASSERT_EQ(named.size(), 1u);
  EXPECT_EQ(named[0].a, 4);
  EXPECT_EQ(named[0].b, 11);
  EXPECT_EQ(named[0].reason, "their readings fit each other's places along the border in 6 of 6 frames with signal");
  EXPECT_EQ(dead.dead().size(), 1u);
  EXPECT_TRUE(dead.swapped().empty());
  crossed.reset();
  EXPECT_TRUE(crossed.swapped().empty());  // fewer than 5 frames with signal: no verdict
}

}  // namespace
}  // namespace emit
