// Recordings (recording.hpp): Recorder writes them, FileSource replays them as fast as possible or
// at the recorded pace, and malformed files are one-line errors naming the file.
#include <cmath>
#include <filesystem>
#include <fstream>
#include <random>

#include <gtest/gtest.h>

#include "allocation_counter.hpp"
#include "core/scan.hpp"
#include "emit/acquire/device_source.hpp"
#include "emit/acquire/file_source.hpp"
#include "emit/acquire/recorder.hpp"
#include "emit/acquire/recording.hpp"
#include "emit/core/errors.hpp"
#include "emit/sensor/adc.hpp"
#include "emit/sensor/sensor_json.hpp"
#include "fake_board.hpp"
#include "test_support.hpp"

namespace emit {
namespace {

using std::chrono::milliseconds;
using Clock = std::chrono::steady_clock;

/// Frames as a board sends them: counts anywhere in the 12-bit range, 50 frames/s from board time 7 s.
std::vector<RawFrame> board_like_frames(const Sensor& sensor, int count) {
  std::mt19937_64 rng(3);
  std::uniform_int_distribution<int> code(0, (1 << sensor.adc.bits) - 1);
  std::vector<RawFrame> frames(static_cast<std::size_t>(count));
  for (int k = 0; k < count; ++k) {
    RawFrame& f = frames[static_cast<std::size_t>(k)];
    f.electrode_count = sensor.electrode_count();
    f.adc_bits = sensor.adc.bits;
    f.oversampling = 1 + k % 4;
    f.counts.resize(static_cast<std::size_t>(f.electrode_count) * static_cast<std::size_t>(f.electrode_count));
    for (auto& c : f.counts) c = static_cast<std::uint16_t>(code(rng));
    f.sequence = static_cast<std::uint32_t>(k);
    f.timestamp_us = 7'000'000u + 20'000u * static_cast<std::uint32_t>(k);
  }
  return frames;
}

std::string record(const std::string& path, const Sensor& sensor, const std::vector<RawFrame>& frames) {
  Recorder recorder(path, sensor);
  for (const RawFrame& f : frames) recorder.record(f);
  EXPECT_TRUE(std::filesystem::exists(path + ".partial"));  // written beside, not over, the target
  EXPECT_FALSE(std::filesystem::exists(path));
  recorder.close();
  EXPECT_FALSE(std::filesystem::exists(path + ".partial"));
  return path;
}

std::vector<char> read_bytes(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}
void write_bytes(const std::string& path, const std::vector<char>& bytes) {
  std::ofstream(path, std::ios::binary).write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
}

/// The message of the InvalidInput or IoError that opening or replaying `path` throws.
std::string replay_error(const std::string& path, const Sensor& sensor) {
  try {
    FileSource source(path, sensor, true);
    SourceFrame frame;
    for (;;) source.next(frame, milliseconds(0));
  } catch (const Error& e) {
    return e.what();
  }
}

TEST(Recording, ReplaysAsFastAsPossibleWhatTheBoardSent) {
  const Sensor sensor = default_sensor();
  const std::vector<RawFrame> frames = board_like_frames(sensor, 20);
  const std::string path = record(test::temp_folder("recording_fast") + "/rec.bin", sensor, frames);
  // 32-byte header + 20 packets of 532 bytes: the format is as compact as packet v1.
  EXPECT_EQ(std::filesystem::file_size(path), 32u + 20u * 532u);

  const std::unique_ptr<FrameSource> source = open_device_source("file:" + path, sensor, {.frames_per_s = 0});
  ASSERT_NE(source, nullptr);
  SourceFrame frame;
  const auto start = Clock::now();
  for (const RawFrame& original : frames) {
    ASSERT_TRUE(source->next(frame, milliseconds(0)));
    // The packet as it was sent, and its counts as volts: code · step, the decoder's exact rule.
    EXPECT_EQ(frame.raw.counts, original.counts);
    EXPECT_EQ(frame.raw.oversampling, original.oversampling);
    EXPECT_EQ(frame.raw.timestamp_us, original.timestamp_us);
    EXPECT_EQ(frame.volts, to_volts(original, sensor.adc.vref_V));
    EXPECT_EQ(frame.sequence, original.sequence);
    EXPECT_DOUBLE_EQ(frame.board_time_s, 1e-6 * original.timestamp_us);
  }
  // 0.38 s of recording came out at once: far faster than its pace.
  EXPECT_LT(Clock::now() - start, milliseconds(100));
  EXPECT_TRUE(source->finished());  // as the last frame went out, so a reader stops without asking again
  try {
    source->next(frame, milliseconds(0));
    FAIL() << "a frame after the last";
  } catch (const IoError& e) {
    EXPECT_EQ(std::string(e.what()), path + ": end of recording");
  }
  EXPECT_TRUE(source->finished());
}

TEST(Recording, ReplaysAtTheRecordedPace) {
  const Sensor sensor = default_sensor();
  const std::vector<RawFrame> frames = board_like_frames(sensor, 20);
  const std::string path = record(test::temp_folder("recording_paced") + "/rec.bin", sensor, frames);
  FileSource source(path, sensor, false);
  SourceFrame frame;
  std::vector<Clock::time_point> handed_out;
  while (handed_out.size() < frames.size())
    if (source.next(frame, milliseconds(5)))
      handed_out.push_back(frame.received);  // 5 ms < the 20 ms gaps: false in between
  const double span_s = 1e-6 * (frames.back().timestamp_us - frames.front().timestamp_us);  // 0.38 s
  const double elapsed_s = std::chrono::duration<double>(handed_out.back() - handed_out.front()).count();
  std::printf("recorded span %.3f s, replayed in %.3f s\n", span_s, elapsed_s);
  // A frame is never handed out before its time (sleep_until does not wake early; timestamps are
  // whole µs); late by a loaded machine's scheduling at most, not by a frame's worth per frame.
  EXPECT_GE(elapsed_s, span_s - 1e-5);
  EXPECT_LT(elapsed_s, span_s + 0.25);
  for (std::size_t k = 1; k < handed_out.size(); ++k)
    EXPECT_GE(std::chrono::duration<double>(handed_out[k] - handed_out[0]).count(),
              0.02 * static_cast<double>(k) - 1e-5);
}

// Recording and replaying frames allocate nothing per frame (after the first replayed frame sized
// the caller's buffer).
TEST(Recording, AllocatesNothingPerFrame) {
  const Sensor sensor = default_sensor();
  const std::vector<RawFrame> frames = board_like_frames(sensor, 20);
  const std::string path = test::temp_folder("recording_alloc") + "/rec.bin";
  Recorder recorder(path, sensor);
  recorder.record(frames[0]);
  {
    test::AllocationCounter counter;
    for (std::size_t k = 1; k < frames.size(); ++k) recorder.record(frames[k]);
    EXPECT_EQ(counter.count(), 0);
  }
  recorder.close();
  FileSource source(path, sensor, true);
  SourceFrame frame;
  ASSERT_TRUE(source.next(frame, milliseconds(0)));
  test::AllocationCounter counter;
  for (std::size_t k = 1; k < frames.size(); ++k) ASSERT_TRUE(source.next(frame, milliseconds(0)));
  EXPECT_EQ(counter.count(), 0);
}

TEST(Recording, RecordsADecodedPacketByteForByte) {
  test::FakeBoard board;
  firmware::Scanner scanner({});
  scanner.scan_and_send(board);
  PacketDecoder decoder;
  const std::string path = test::temp_folder("recording_raw") + "/rec.bin";
  {
    Recorder recorder(path, default_sensor());
    decoder.feed(board.written, [&](const RawFrame& raw) { recorder.record(raw); });
    EXPECT_EQ(recorder.frames(), 1u);
  }  // the destructor closes and renames
  const std::vector<char> bytes = read_bytes(path);
  ASSERT_EQ(bytes.size(), 32 + board.written.size());
  EXPECT_TRUE(
      std::equal(board.written.begin(), board.written.end(), reinterpret_cast<const std::uint8_t*>(bytes.data()) + 32));
}

TEST(Recording, MalformedFilesAreOneLineErrorsNamingTheFile) {
  const Sensor sensor = default_sensor();
  const std::string folder = test::temp_folder("recording_bad");
  const std::string good = record(folder + "/good.bin", sensor, board_like_frames(sensor, 10));
  std::vector<char> bytes = read_bytes(good);

  const std::string truncated = folder + "/truncated.bin";
  write_bytes(truncated, std::vector<char>(bytes.begin(), bytes.end() - 100));  // a crash mid-packet
  {
    // Its 9 whole frames first (a crashed run's frames are worth replaying), then the cut, named
    // by frame and byte (32 + 9·532 = 4820), and never taken for the recording's end.
    FileSource source(truncated, sensor, true);
    EXPECT_EQ(source.frame_count(), 9u);
    SourceFrame frame;
    for (int k = 0; k < 9; ++k) EXPECT_TRUE(source.next(frame, milliseconds(0))) << k;
    EXPECT_FALSE(source.finished());
  }
  EXPECT_EQ(replay_error(truncated, sensor), truncated + ": truncated: frame 9 (byte 4820) has 432 of its 532 bytes");

  const std::string foreign = folder + "/foreign.bin";
  write_bytes(foreign, std::vector<char>(100, 'x'));
  EXPECT_EQ(replay_error(foreign, sensor), foreign + ": not an emit recording (it does not start with EMITREC1)");

  const std::string tiny = folder + "/tiny.bin";
  write_bytes(tiny, std::vector<char>(bytes.begin(), bytes.begin() + 10));
  EXPECT_NE(replay_error(tiny, sensor).find(tiny + ": not an emit recording"), std::string::npos);

  const std::string corrupt = folder + "/corrupt.bin";
  std::vector<char> flipped = bytes;
  flipped[32 + 5 * 532 + 100] ^= 0x04;  // a payload bit of frame 5
  write_bytes(corrupt, flipped);
  FileSource source(corrupt, sensor, true);
  SourceFrame frame;
  for (int k = 0; k < 5; ++k) EXPECT_TRUE(source.next(frame, milliseconds(0)));  // the frames before are fine
  EXPECT_EQ(replay_error(corrupt, sensor),
            corrupt + ": frame 5 (byte 2692) is not a valid packet (sync, header or CRC)");

  Sensor eight = sensor;
  eight.electrodes.resize(8);
  EXPECT_EQ(replay_error(good, eight), good + ": recorded with 16 electrodes, but the sensor has 8");
  EXPECT_THROW(open_device_source("file:" + folder + "/missing.bin", sensor, {}), IoError);
}

// The 32-byte header round trips exactly (vref as the double's own bits), and each field that
// cannot be is named.
TEST(Recording, HeaderRoundTripsAndImpossibleFieldsAreNamed) {
  const RecordingHeader header{32, 10, 3.3, 1'700'000'000'123'456u};
  std::uint8_t bytes[recording_header_size];
  encode_recording_header(header, bytes);
  const RecordingHeader back = decode_recording_header(bytes, "r.emitrec");
  EXPECT_EQ(back.electrode_count, 32);
  EXPECT_EQ(back.adc_bits, 10);
  EXPECT_EQ(back.vref_V, 3.3);
  EXPECT_EQ(back.start_unix_us, header.start_unix_us);
  auto error_of = [](RecordingHeader h, std::uint16_t version, std::uint16_t size) -> std::string {
    std::uint8_t b[recording_header_size];
    encode_recording_header(h, b);
    b[8] = static_cast<std::uint8_t>(version), b[9] = 0, b[10] = static_cast<std::uint8_t>(size), b[11] = 0;
    try {
      decode_recording_header(b, "r.emitrec");
    } catch (const InvalidInput& e) {
      return e.what();
    }
    return "no error";
  };
  EXPECT_EQ(error_of(header, 2, 32), "r.emitrec: recording format version 2; this emit reads version 1");
  EXPECT_EQ(error_of(header, 1, 40), "r.emitrec: recording header size 40 bytes; version 1 has 32");
  EXPECT_EQ(error_of({65, 10, 3.3, 0}, 1, 32), "r.emitrec: recording header: electrode count 65 is outside 2..64");
  EXPECT_EQ(error_of({16, 17, 3.3, 0}, 1, 32), "r.emitrec: recording header: ADC bits 17 outside 1..16");
  EXPECT_EQ(error_of({16, 12, -3.3, 0}, 1, 32),
            "r.emitrec: recording header: the ADC reference voltage is not a positive number");
}

}  // namespace
}  // namespace emit
