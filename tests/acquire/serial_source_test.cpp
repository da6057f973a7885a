// The serial path end to end: the firmware core's Scanner, on a
// host board that reads the digital twin, writes packets v1 to a pseudo-terminal; the host opens
// the other end as "serial:/dev/pts/N", decodes, and reconstructs the presses the twin was given.
// Then: garbage injected mid-stream loses only the frames it touches; a pulled cable is retried
// and the stream resumes.
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <random>
#include <thread>

#include <gtest/gtest.h>

#include "allocation_counter.hpp"
#include "core/scan.hpp"
#include "emit/acquire/device_source.hpp"
#include "emit/acquire/serial_port.hpp"
#include "emit/acquire/serial_source.hpp"
#include "emit/core/errors.hpp"
#include "emit/frame/contact_fitter.hpp"
#include "emit/frame/reconstructor.hpp"
#include "emit/model/fit_model.hpp"
#include "emit/model/method.hpp"
#include "emit/sensor/sensor_json.hpp"
#include "emit/twin/twin_board.hpp"
#include "fake_board.hpp"
#include "pseudo_terminal.hpp"
#include "test_support.hpp"

namespace emit {
namespace {

using std::chrono::milliseconds;
using Clock = std::chrono::steady_clock;

/// Read frames from `source` until `count` arrived or `patience` ran out.
std::vector<SourceFrame> receive(FrameSource& source, std::size_t count, std::chrono::seconds patience) {
  std::vector<SourceFrame> frames;
  const auto deadline = Clock::now() + patience;
  SourceFrame frame;
  while (frames.size() < count && Clock::now() < deadline)
    if (source.next(frame, milliseconds(100))) frames.push_back(frame);
  return frames;
}

SerialSource& as_serial(FrameSource& source) { return dynamic_cast<SerialSource&>(source); }

/// Packets of `count` frames from the firmware core on the fake board (counts 100·g + s, valid for
/// a 12-bit ADC), each packet its own byte string.
std::vector<std::vector<std::uint8_t>> fake_packets(int count) {
  test::FakeBoard board;
  firmware::Scanner scanner({});
  std::vector<std::vector<std::uint8_t>> packets;
  for (int k = 0; k < count; ++k) {
    board.written.clear();
    scanner.scan_and_send(board);
    packets.push_back(board.written);
  }
  return packets;
}

/// Occurrences of the sync "EM" in `bytes`.
int sync_count(const std::vector<std::uint8_t>& bytes) {
  int count = 0;
  for (std::size_t k = 0; k + 1 < bytes.size(); ++k) count += bytes[k] == 0x45 && bytes[k + 1] == 0x4D;
  return count;
}

/// `count` random bytes, none an 'E' (0x45), so none can start a sync.
std::vector<std::uint8_t> garbage(std::mt19937& rng, int count) {
  std::vector<std::uint8_t> bytes;
  std::uniform_int_distribution<int> byte(0, 255);
  while (static_cast<int>(bytes.size()) < count)
    if (const int b = byte(rng); b != 0x45) bytes.push_back(static_cast<std::uint8_t>(b));
  return bytes;
}

// Six scans of the twin through a real tty: two untouched, then single 10 N presses (5 mm
// indenter) at three places. Model-based fitting (the default method of emit reconstruct) finds
// each press where the twin had it.
TEST(SerialEndToEnd, TwinFramesCrossAPtyAndReconstructToThePresses) {
  const Sensor sensor = default_sensor();
  const std::vector<std::vector<Press>> presses = {{}, {}, {{20, 20, 5, 10}}, {{40, 35, 5, 10}}, {{30, 45, 5, 10}}, {}};
  TwinOptions twin_options;
  twin_options.mesh_seed = 5;  // another mesh than the reconstruction's (no inverse crime)
  Twin twin(sensor, twin_options);

  test::PseudoTerminal pty;
  const std::unique_ptr<FrameSource> source = open_device_source("serial:" + pty.slave_path(), sensor, {});
  ASSERT_NE(source, nullptr);
  EXPECT_EQ(source->description(), "serial:" + pty.slave_path() + " at 921600 baud");

  std::thread board_thread([&] {
    TwinBoard board(twin, fd_sink(pty.master()));
    firmware::Scanner scanner({});
    for (const std::vector<Press>& p : presses) {
      board.set_presses(p);
      scanner.scan_and_send(board);
    }
  });
  const std::vector<SourceFrame> frames = receive(*source, presses.size(), std::chrono::seconds(120));
  board_thread.join();
  ASSERT_EQ(frames.size(), presses.size());
  const SerialStats stats = as_serial(*source).stats();
  EXPECT_EQ(stats.decoder.frames, presses.size());
  EXPECT_EQ(stats.decoder.corrupt + stats.decoder.dropped + stats.decoder.garbage_bytes, 0u);
  for (std::size_t k = 0; k < frames.size(); ++k) {
    EXPECT_EQ(frames[k].sequence, k);  // the Scanner numbers frames from 0
    EXPECT_EQ(frames[k].volts.rows(), 16);
    if (k > 0) {
      EXPECT_GT(frames[k].board_time_s, frames[k - 1].board_time_s);  // each scan after the last
    }
  }

  const ReconstructionModel model = build_reconstruction_model(sensor, operator_options(Method::paper), "");
  const FitModel fit_model = build_fit_model(sensor);
  const FitPrecompute fit(sensor, fit_model.mesh, fit_model.green, model.measurements);
  Reconstructor reconstructor(model, fit, FitCalibration::uncalibrated(sensor));
  reconstructor.set_reference({frames[0].volts, 1});  // the first untouched frame
  for (std::size_t k = 1; k < frames.size(); ++k) {
    const std::vector<Contact>& contacts = reconstructor.process(frames[k].volts);
    double force_N = 0;
    for (const Contact& c : contacts) {
      std::printf("frame %zu: contact %.2f, %.2f, %.3f N, %.1f mm2\n", k, c.x_mm, c.y_mm, c.force_N, c.area_mm2);
      force_N += c.force_N;
    }
    if (presses[k].empty()) {
      // The fitter may explain an untouched frame's noise (two frames' worth: the reference is one
      // frame too) with a faint contact; it must carry under 1 % of a 10 N press.
      EXPECT_LT(force_N, 0.1) << "frame " << k;
      continue;
    }
    ASSERT_FALSE(contacts.empty()) << "frame " << k;
    const Contact& strongest =
        *std::max_element(contacts.begin(), contacts.end(),
                          [](const Contact& a, const Contact& b) { return a.force_N < b.force_N; });
    const Press& press = presses[k][0];
    const double error_mm = std::hypot(strongest.x_mm - press.x_mm, strongest.y_mm - press.y_mm);
    std::printf("frame %zu: press %.0f, %.0f -> %.3f mm off\n", k, press.x_mm, press.y_mm, error_mm);
    // contact_fitter_test: single presses on the twin come out 0.3 mm off on average (the 60 mm
    // sheet's target) with the same noisy untouched reference; a single one within 0.5 mm.
    EXPECT_LT(error_mm, 0.5) << "frame " << k;
    // Anything else found beside the press is faint (the same noise bound as untouched frames).
    EXPECT_LT(force_N - strongest.force_N, 0.1) << "frame " << k;
  }
}

// Garbage between and inside packets, a cut-off packet and a flipped bit: exactly the packets
// touched are lost, and the decoder's counters account for every byte.
TEST(SerialEndToEnd, GarbageMidStreamLosesOnlyTheFramesItTouches) {
  const std::vector<std::vector<std::uint8_t>> packets = fake_packets(10);
  const std::size_t size = packets[0].size();  // 532
  std::mt19937 rng(7);
  const std::vector<std::uint8_t> between = garbage(rng, 37), inside = garbage(rng, 13);
  std::vector<std::uint8_t> stream;
  const auto append = [&](const std::vector<std::uint8_t>& bytes) {
    stream.insert(stream.end(), bytes.begin(), bytes.end());
  };
  for (int k = 0; k < 10; ++k) {
    std::vector<std::uint8_t> packet = packets[static_cast<std::size_t>(k)];
    if (k == 1) append(between);                                                          // 37 random bytes
    if (k == 3) append(std::vector<std::uint8_t>(packet.begin(), packet.begin() + 100));  // a cut packet
    if (k == 5) packet.insert(packet.begin() + 200, inside.begin(), inside.end());        // bytes inside a payload
    if (k == 7) packet[300] ^= 0x01;                                                      // one bit flipped
    append(packet);
  }
  // The accounting below assumes the only syncs are the packets' own (and the cut packet's).
  ASSERT_EQ(sync_count(stream), 11);

  test::PseudoTerminal pty;
  const Sensor sensor = default_sensor();
  const std::unique_ptr<FrameSource> source = open_device_source("serial:" + pty.slave_path(), sensor, {});
  std::thread writer([&] {
    // In uneven chunks, so packets arrive split anywhere.
    for (std::size_t at = 0; at < stream.size(); at += 211)
      fd_sink(pty.master())(stream.data() + at, std::min<std::size_t>(211, stream.size() - at));
  });
  const std::vector<SourceFrame> frames = receive(*source, 8, std::chrono::seconds(10));
  writer.join();
  SourceFrame extra;
  EXPECT_FALSE(source->next(extra, milliseconds(200)));  // nothing more arrives

  std::vector<std::uint64_t> sequences;
  sequences.reserve(frames.size());
  for (const SourceFrame& f : frames) sequences.push_back(f.sequence);
  // Packets 5 (bytes inside) and 7 (bit flipped) are lost; the cut packet costs its neighbour nothing.
  EXPECT_EQ(sequences, (std::vector<std::uint64_t>{0, 1, 2, 3, 4, 6, 8, 9}));
  const DecoderStats stats = as_serial(*source).stats().decoder;
  EXPECT_EQ(stats.frames, 8u);
  EXPECT_EQ(stats.corrupt, 3u);  // the cut packet, packet 5, packet 7: each rejected at its CRC
  EXPECT_EQ(stats.dropped, 2u);  // sequence numbers 5 and 7 missing
  // Skipped bytes: the 37 between packets; the cut packet's 100 less its sync; packet 5's 532 + 13
  // less its sync; packet 7's 532 less its sync.
  EXPECT_EQ(stats.garbage_bytes, 37u + 98u + (size + 13 - 2) + (size - 2));
  // The frames that arrived are the board's: value [g, s] = (100·g + s) counts of 4095 over 3.3 V.
  EXPECT_NEAR(frames[5].volts(3, 7), 307 / 4095.0 * sensor.adc.vref_V, 1e-12);
}

// The serial port itself: a read times out with nothing to read, returns what the other end
// wrote, and reports the other end's closing as a disconnect (not an error thrown, not 0 bytes).
TEST(SerialPort, ReadsTimesOutAndReportsADisconnect) {
  test::PseudoTerminal pty;
  SerialPort port;
  port.open(pty.slave_path(), 921600);
  std::array<std::uint8_t, 64> buffer{};
  const auto start = Clock::now();
  SerialRead read = port.read_some(buffer, milliseconds(100));
  EXPECT_EQ(read.bytes, 0u);
  EXPECT_FALSE(read.disconnected);
  EXPECT_GE(Clock::now() - start, milliseconds(100));                 // poll(2) waits at least its timeout
  const std::uint8_t hello[] = {0x00, 0x0A, 0x0D, 0x11, 0x13, 0xFF};  // NUL, LF, CR, XON, XOFF: raw
  fd_sink(pty.master())(hello, sizeof hello);
  read = port.read_some(buffer, milliseconds(1000));
  ASSERT_EQ(read.bytes, sizeof hello);
  EXPECT_TRUE(std::equal(hello, hello + sizeof hello, buffer.begin()));
  pty.close_master();
  read = port.read_some(buffer, milliseconds(1000));
  EXPECT_TRUE(read.disconnected);
  EXPECT_FALSE(port.error().empty());
  EXPECT_THROW(port.open("/dev/emit-no-such-port", 921600), IoError);
  EXPECT_NE(port.error().find("/dev/emit-no-such-port"), std::string::npos);
}

// The cable pulled and plugged back: a pty cannot come back under the same name, so the source
// opens a symlink that is re-pointed to a new pty, as udev re-points /dev/serial/by-id/… to the
// board's new ttyUSB. The source reports "disconnected, retrying", reopens within its retry
// interval, and frames resume; the new stream's restarted sequence numbers count no drops.
TEST(SerialEndToEnd, ReconnectsWhenTheDeviceComesBack) {
  const std::string folder = test::temp_folder("serial_reconnect");
  const std::string link = folder + "/board";
  const std::vector<std::vector<std::uint8_t>> packets = fake_packets(3);
  const Sensor sensor = default_sensor();

  auto first = std::make_unique<test::PseudoTerminal>();
  std::filesystem::create_symlink(first->slave_path(), link);
  const std::unique_ptr<FrameSource> source = open_device_source("serial:" + link, sensor, {});
  for (const auto& p : packets) fd_sink(first->master())(p.data(), p.size());
  EXPECT_EQ(receive(*source, 3, std::chrono::seconds(10)).size(), 3u);

  first.reset();  // pulled
  SourceFrame frame;
  EXPECT_FALSE(source->next(frame, milliseconds(200)));
  EXPECT_FALSE(as_serial(*source).connected());
  EXPECT_EQ(as_serial(*source).status().rfind("disconnected, retrying every 0.5 s", 0), 0u)
      << as_serial(*source).status();

  test::PseudoTerminal second;  // plugged back: a new device node, the link re-pointed
  std::filesystem::create_symlink(second.slave_path(), link + ".new");
  std::filesystem::rename(link + ".new", link);
  for (const auto& p : packets) fd_sink(second.master())(p.data(), p.size());
  const auto plugged = Clock::now();
  const std::vector<SourceFrame> frames = receive(*source, 3, std::chrono::seconds(10));
  ASSERT_EQ(frames.size(), 3u);
  // Retries come every 0.5 s: the first after the plug is at most 0.5 s away (+ scheduling).
  EXPECT_LT(Clock::now() - plugged, milliseconds(1500));
  EXPECT_EQ(frames[0].sequence, 0u);
  EXPECT_TRUE(as_serial(*source).connected());
  const SerialStats stats = as_serial(*source).stats();
  EXPECT_EQ(stats.disconnects, 1u);
  EXPECT_EQ(stats.reconnects, 1u);
  EXPECT_EQ(stats.decoder.frames, 6u);
  EXPECT_EQ(stats.decoder.dropped + stats.decoder.corrupt, 0u);
}

// A device removed for good: the source retries for its reconnection time (here 1 s, every
// 0.1 s), then fails with the port's last error, for good (frame_source.hpp: never finished()).
TEST(SerialEndToEnd, APortGoneForGoodFailsAfterItsReconnectionTime) {
  const std::vector<std::vector<std::uint8_t>> packets = fake_packets(3);
  auto pty = std::make_unique<test::PseudoTerminal>();
  SerialSource source(pty->slave_path(), default_serial_baud, default_sensor(), milliseconds(100), milliseconds(1000));
  for (const auto& p : packets) fd_sink(pty->master())(p.data(), p.size());
  EXPECT_EQ(receive(source, 3, std::chrono::seconds(10)).size(), 3u);
  pty.reset();  // pulled, and never plugged back
  SourceFrame frame;
  const auto pulled = Clock::now();
  std::string failure;
  try {
    while (Clock::now() - pulled < std::chrono::seconds(10)) EXPECT_FALSE(source.next(frame, milliseconds(50)));
  } catch (const IoError& e) {
    failure = e.what();
  }
  const double after_s = std::chrono::duration<double>(Clock::now() - pulled).count();
  // Not before the reconnection time; after it by at most a retry (0.1 s) and a poll (0.05 s),
  // with 0.35 s for a loaded machine's scheduling.
  EXPECT_GE(after_s, 1.0);
  EXPECT_LT(after_s, 1.5);
  EXPECT_EQ(failure.rfind(source.description() + ": disconnected for 1 s and not back (the last try: ", 0), 0u)
      << failure;
  EXPECT_FALSE(source.finished());
  EXPECT_THROW(source.next(frame, milliseconds(0)), IoError);
}

// The per-frame serial path (read, decode, counts to volts, hand out) allocates nothing once the
// caller's frame has its size.
TEST(SerialEndToEnd, AllocatesNothingPerFrameOnceWarmedUp) {
  const std::vector<std::vector<std::uint8_t>> packets = fake_packets(100);
  test::PseudoTerminal pty;
  const std::unique_ptr<FrameSource> source = open_device_source("serial:" + pty.slave_path(), default_sensor(), {});
  std::thread writer([&] {
    for (const auto& p : packets) fd_sink(pty.master())(p.data(), p.size());
  });
  std::size_t received = receive(*source, 2, std::chrono::seconds(10)).size();  // warm-up
  SourceFrame frame;  // its first frame sizes its volts and counts (once, as the source documents)
  for (const auto deadline = Clock::now() + std::chrono::seconds(10); received < 3 && Clock::now() < deadline;)
    received += source->next(frame, milliseconds(100));
  long allocations = 0;
  {
    test::AllocationCounter counter;
    while (received < packets.size() && source->next(frame, milliseconds(2000))) ++received;
    allocations = counter.count();
  }
  writer.join();
  EXPECT_EQ(received, packets.size());
  EXPECT_EQ(allocations, 0);
}

TEST(DeviceSource, ParsesSpecsAndNamesWhatIsWrong) {
  const Sensor sensor = default_sensor();
  EXPECT_EQ(open_device_source("sim", sensor, {}), nullptr);
  EXPECT_THROW(open_device_source("serial:", sensor, {}), InvalidInput);
  EXPECT_THROW(open_device_source("serial:/dev/ttyUSB0@fast", sensor, {}), InvalidInput);
  try {
    open_device_source("serial:/dev/emit-no-such-port@115200", sensor, {});
    FAIL() << "opened a port that does not exist";
  } catch (const IoError& e) {
    EXPECT_NE(std::string(e.what()).find("/dev/emit-no-such-port"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("115200"), std::string::npos) << e.what();
  }
}

// A board with another electrode count than the sensor's is a clear error naming both.
TEST(SerialEndToEnd, RejectsABoardWithAnotherElectrodeCount) {
  test::FakeBoard board;
  firmware::ScanOptions options;
  options.electrode_count = 8;
  firmware::Scanner scanner(options);
  scanner.scan_and_send(board);
  test::PseudoTerminal pty;
  const std::unique_ptr<FrameSource> source = open_device_source("serial:" + pty.slave_path(), default_sensor(), {});
  fd_sink(pty.master())(board.written.data(), board.written.size());
  SourceFrame frame;
  try {
    for (int k = 0; k < 50; ++k) source->next(frame, milliseconds(100));
    FAIL() << "no error";
  } catch (const IoError& e) {
    EXPECT_NE(std::string(e.what()).find("frames of 8 electrodes but the sensor has 16"), std::string::npos)
        << e.what();
  }
  // For good: never finished (a normal end), the same failure again on every call.
  EXPECT_FALSE(source->finished());
  EXPECT_THROW(source->next(frame, milliseconds(0)), IoError);
}

}  // namespace
}  // namespace emit
