// A recording replayed in a loop (file_source.hpp, `emit live --loop`): the packets come round
// again and again, and the numbers a reader sees go on as if the board had kept sending, with no
// gap and no step back, across passes and across the 32-bit counters' wrap.
#include <cstdint>
#include <filesystem>
#include <random>

#include <gtest/gtest.h>

#include "allocation_counter.hpp"
#include "emit/acquire/device_source.hpp"
#include "emit/acquire/file_source.hpp"
#include "emit/acquire/recorder.hpp"
#include "emit/core/errors.hpp"
#include "emit/live/open_source.hpp"
#include "emit/sensor/adc.hpp"
#include "emit/sensor/sensor_json.hpp"
#include "test_support.hpp"

namespace emit {
namespace {

using std::chrono::milliseconds;
using Clock = std::chrono::steady_clock;

/// `count` frames of random counts, numbered from `first_sequence`, `interval_us` apart from `first_us`.
std::string record_frames(const std::string& path, const Sensor& sensor, int count, std::uint32_t first_sequence,
                          std::uint32_t first_us, std::uint32_t interval_us, std::vector<RawFrame>* frames = nullptr) {
  std::mt19937_64 rng(5);
  std::uniform_int_distribution<int> code(0, (1 << sensor.adc.bits) - 1);
  Recorder recorder(path, sensor);
  for (int k = 0; k < count; ++k) {
    RawFrame f;
    f.electrode_count = sensor.electrode_count();
    f.adc_bits = sensor.adc.bits;
    f.oversampling = 1;
    f.counts.resize(static_cast<std::size_t>(f.electrode_count) * static_cast<std::size_t>(f.electrode_count));
    for (auto& c : f.counts) c = static_cast<std::uint16_t>(code(rng));
    f.sequence = first_sequence + static_cast<std::uint32_t>(k);  // modulo 2^32, as a board's
    f.timestamp_us = first_us + interval_us * static_cast<std::uint32_t>(k);
    recorder.record(f);
    if (frames) frames->push_back(f);
  }
  recorder.close();
  return path;
}

// Five frames, 17 read: three and a bit passes, each frame's counts the recording's in turn, the
// numbers going on by one and the board's time by the recording's 20 ms a frame, exactly (whole
// µs on both sides, so the doubles differ only by rounding: 1 ns).
TEST(FileSourceLoop, NumbersGoOnAcrossPasses) {
  const Sensor sensor = default_sensor();
  std::vector<RawFrame> frames;
  const std::string path =
      record_frames(test::temp_folder("loop_numbers") + "/rec.bin", sensor, 5, 100, 7'000'000, 20'000, &frames);
  const std::unique_ptr<FrameSource> source =
      open_device_source("file:" + path, sensor, {.frames_per_s = 0, .loop = true});
  EXPECT_NE(source->description().find("in a loop"), std::string::npos) << source->description();
  SourceFrame frame;
  for (int k = 0; k < 17; ++k) {
    ASSERT_TRUE(source->next(frame, milliseconds(0))) << k;
    const RawFrame& original = frames[static_cast<std::size_t>(k % 5)];
    EXPECT_EQ(frame.raw.counts, original.counts) << k;
    EXPECT_EQ(frame.volts, to_volts(original, sensor.adc.vref_V)) << k;
    EXPECT_EQ(frame.sequence, 100u + static_cast<std::uint64_t>(k)) << k;
    EXPECT_EQ(frame.raw.sequence, 100u + static_cast<std::uint32_t>(k)) << k;  // the packet says the same
    EXPECT_EQ(frame.raw.timestamp_us, 7'000'000u + 20'000u * static_cast<std::uint32_t>(k)) << k;
    EXPECT_NEAR(frame.board_time_s, 7.0 + 0.02 * k, 1e-9) << k;
    EXPECT_FALSE(source->finished()) << k;  // a loop never ends by itself
  }
  EXPECT_EQ(dynamic_cast<const FileSource&>(*source).passes(), 3u);
}

// Numbered and stamped near the top of the 32-bit counters: the packets' fields wrap as a board's
// do, and the board's clock (board_clock.hpp) carries the time on across the wrap, +10 ms a frame.
TEST(FileSourceLoop, BoardTimeGoesOnAcrossTheCountersWrap) {
  const Sensor sensor = default_sensor();
  const std::uint32_t near_top_us = 0xFFFFFFFFu - 45'000u;  // 4.5 frames before the wrap
  const std::string path =
      record_frames(test::temp_folder("loop_wrap") + "/rec.bin", sensor, 3, 0xFFFFFFFEu, near_top_us, 10'000);
  FileSource source(path, sensor, true, true);
  SourceFrame frame;
  double previous_s = 0;
  std::uint32_t previous_sequence = 0;
  for (int k = 0; k < 10; ++k) {
    ASSERT_TRUE(source.next(frame, milliseconds(0)));
    if (k > 0) {
      EXPECT_NEAR(frame.board_time_s - previous_s, 0.01, 1e-9) << k;
      EXPECT_EQ(frame.raw.sequence, previous_sequence + 1u) << k;  // modulo 2^32
    }
    previous_s = frame.board_time_s;
    previous_sequence = frame.raw.sequence;
  }
  EXPECT_EQ(previous_sequence, 0xFFFFFFFEu + 9u);  // wrapped to 7
}

// At the recorded pace, the loop keeps the pace across the seam: 12 frames of a 4-frame, 20 ms
// recording take 11 intervals (0.22 s), not less (no frame early) and not much more (a loaded
// machine's scheduling, as recording_test's paced replay allows).
TEST(FileSourceLoop, KeepsThePaceAcrossTheSeam) {
  const Sensor sensor = default_sensor();
  const std::string path = record_frames(test::temp_folder("loop_paced") + "/rec.bin", sensor, 4, 0, 1'000'000, 20'000);
  FileSource source(path, sensor, false, true);
  SourceFrame frame;
  std::vector<Clock::time_point> handed_out;
  while (handed_out.size() < 12)
    if (source.next(frame, milliseconds(5))) handed_out.push_back(frame.received);
  const double elapsed_s = std::chrono::duration<double>(handed_out.back() - handed_out.front()).count();
  EXPECT_GE(elapsed_s, 0.22 - 1e-5);
  EXPECT_LT(elapsed_s, 0.22 + 0.25);
}

// A one-frame recording has no interval of its own: the loop steps the time by 20 ms (50 frames/s,
// the simulator's default pace), so the clock still moves on.
TEST(FileSourceLoop, OneFrameRecordingStepsByTheDefaultInterval) {
  const Sensor sensor = default_sensor();
  const std::string path = record_frames(test::temp_folder("loop_one") + "/rec.bin", sensor, 1, 9, 500, 0);
  FileSource source(path, sensor, true, true);
  SourceFrame frame;
  for (int k = 0; k < 4; ++k) {
    ASSERT_TRUE(source.next(frame, milliseconds(0)));
    EXPECT_EQ(frame.sequence, 9u + static_cast<std::uint64_t>(k));
    EXPECT_NEAR(frame.board_time_s, 500e-6 + 0.02 * k, 1e-9);
  }
}

// Going round allocates nothing (the soak test's memory stays flat because of it, among others).
TEST(FileSourceLoop, AllocatesNothingPerFrameAcrossPasses) {
  const Sensor sensor = default_sensor();
  const std::string path = record_frames(test::temp_folder("loop_alloc") + "/rec.bin", sensor, 3, 0, 0, 20'000);
  FileSource source(path, sensor, true, true);
  SourceFrame frame;
  ASSERT_TRUE(source.next(frame, milliseconds(0)));
  test::AllocationCounter counter;
  for (int k = 1; k < 20; ++k) ASSERT_TRUE(source.next(frame, milliseconds(0)));
  EXPECT_EQ(counter.count(), 0);
  EXPECT_EQ(source.passes(), 6u);
}

// An empty recording in a loop ends at once, as without one (nothing to go round).
TEST(FileSourceLoop, EmptyRecordingEnds) {
  const Sensor sensor = default_sensor();
  const std::string path = record_frames(test::temp_folder("loop_empty") + "/rec.bin", sensor, 0, 0, 0, 0);
  FileSource source(path, sensor, true, true);
  SourceFrame frame;
  EXPECT_THROW(source.next(frame, milliseconds(0)), IoError);
  EXPECT_TRUE(source.finished());
}

// Only a recording loops: the twin and the board are refused, naming the source.
TEST(FileSourceLoop, OnlyARecordingLoops) {
  const Sensor sensor = default_sensor();
  for (const std::string spec : {"sim", "sim:fixed:20,40", "serial:/dev/null"}) {
    try {
      open_source(spec, sensor, {.loop = true});
      ADD_FAILURE() << spec << " was opened in a loop";
    } catch (const InvalidInput& e) {
      EXPECT_EQ(std::string(e.what()),
                "source \"" + spec + "\": only a recording (file:PATH) can be replayed in a loop");
    }
  }
}

}  // namespace
}  // namespace emit
