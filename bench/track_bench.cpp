// Tracking per frame (frame/contact_tracker.hpp): four fingers sliding, tracked (optimal assignment,
// prediction, velocity), with the filter off and on. The target: at most 20 µs a frame, no allocation
// (tests/frame/contact_tracker_test.cpp counts them: none per frame).
#include <tuple>
#include <vector>

#include <benchmark/benchmark.h>

#include "emit/frame/contact_tracker.hpp"

namespace {

using namespace emit;

/// 200 frames of four fingers 20 mm apart, each sliding 0.3 mm a frame, their outlines full (as a fit's).
std::vector<std::vector<Contact>> four_fingers() {
  std::vector<std::vector<Contact>> frames;
  for (int f = 0; f < 200; ++f) {
    const double s = 0.3 * (f % 100);
    std::vector<Contact> contacts;
    for (const auto& [x, y, force] : {std::tuple{18 + s, 18.0, 8.0}, std::tuple{38.0, 18 + s, 10.0},
                                      std::tuple{18.0, 38 - s, 12.0}, std::tuple{38 - s, 38.0, 9.0}}) {
      Contact c;
      c.x_mm = x, c.y_mm = y, c.force_N = force, c.x_std_mm = c.y_std_mm = 0.05;
      ellipse_outline(Vector2(x, y), 5, 5, 0, c.outline);
      contacts.push_back(c);
    }
    frames.push_back(contacts);
  }
  return frames;
}

void BM_TrackFrame(benchmark::State& state) {
  const std::vector<std::vector<Contact>> frames = four_fingers();
  TrackerOptions options;
  options.filter = state.range(0) != 0;
  ContactTracker tracker(options, 64);  // the live loop's limit
  std::size_t f = 0;
  double time_s = 0;
  for ([[maybe_unused]] auto _ : state) {
    benchmark::DoNotOptimize(tracker.update(frames[f++ % frames.size()], time_s).data());
    time_s += 0.02;
  }
}
BENCHMARK(BM_TrackFrame)->Arg(0)->Arg(1)->ArgName("filter")->Unit(benchmark::kMicrosecond);

}  // namespace
