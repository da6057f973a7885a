// The firmware core's scan sequencer on a recording fake board: visiting order, multiplexer
// addressing and enable, settling delays, oversampling average, frame header, options.
#include <gtest/gtest.h>

#include <string>

#include "core/scan.hpp"
#include "fake_board.hpp"

namespace emit {
namespace {

using firmware::Mux;
using firmware::MuxControl;
using firmware::Scanner;
using firmware::ScanOptions;
using test::FakeBoard;
using Kind = FakeBoard::Kind;

ScanOptions options_n(int n, int oversampling = 1) {
  ScanOptions options;
  options.electrode_count = n;
  options.oversampling = oversampling;
  return options;
}

TEST(FirmwareScan, VisitsEveryPairGroundMajorWithBothMultiplexersEnabled) {
  FakeBoard board;
  Scanner scanner(options_n(16));
  ASSERT_EQ(scanner.error(), nullptr);
  ASSERT_TRUE(scanner.scan(board));
  const auto reads = board.of_kind(Kind::read_adc);
  ASSERT_EQ(reads.size(), 256u);  // 16 × 16 pairs, one reading each
  for (int g = 0; g < 16; ++g)
    for (int s = 0; s < 16; ++s) {
      const auto& read = reads[static_cast<std::size_t>(g) * 16 + static_cast<std::size_t>(s)];
      EXPECT_EQ(read.ground, (MuxControl{static_cast<std::uint8_t>(g), true})) << g << "," << s;
      EXPECT_EQ(read.sense, (MuxControl{static_cast<std::uint8_t>(s), true})) << g << "," << s;
      // The fake reads 100·g + s; stored at [g·N + s].
      EXPECT_EQ(scanner.counts()[g * 16 + s], 100 * g + s);
    }
}

TEST(FirmwareScan, AddressesEachElectrodesChannelFromTheMap) {
  // Electrodes wired to the multiplexers in reverse order, on channels 15, 13, 11, ...: the scan
  // must still visit electrodes in order, addressing each one's channel.
  ScanOptions options = options_n(8);
  for (int e = 0; e < 8; ++e)
    options.channel_of_electrode[static_cast<std::size_t>(e)] = static_cast<std::uint8_t>(15 - 2 * e);
  FakeBoard board;
  Scanner scanner(options);
  ASSERT_EQ(scanner.error(), nullptr);
  ASSERT_TRUE(scanner.scan(board));
  const auto reads = board.of_kind(Kind::read_adc);
  ASSERT_EQ(reads.size(), 64u);
  for (int g = 0; g < 8; ++g)
    for (int s = 0; s < 8; ++s) {
      const auto& read = reads[static_cast<std::size_t>(g) * 8 + static_cast<std::size_t>(s)];
      EXPECT_EQ(read.ground.address, 15 - 2 * g);
      EXPECT_EQ(read.sense.address, 15 - 2 * s);
      EXPECT_EQ(scanner.counts()[g * 8 + s], 100 * (15 - 2 * g) + (15 - 2 * s));
    }
}

TEST(FirmwareScan, CallOrderAndSettlingDelays) {
  // Per (g, s): [ground mux when g changes], sense mux, one wait, `oversampling` reads; the wait is
  // the long one right after the ground changed. Then both multiplexers are disabled.
  ScanOptions options = options_n(4, 3);
  options.settle_after_ground_us = 150;
  options.settle_after_sense_us = 25;
  FakeBoard board;
  Scanner scanner(options);
  ASSERT_TRUE(scanner.scan(board));
  std::vector<FakeBoard::Event> expected;
  expected.push_back({Kind::micros, {}, {}, {}, {}, 1000});
  for (int g = 0; g < 4; ++g) {
    expected.push_back({Kind::set_mux, Mux::ground, {static_cast<std::uint8_t>(g), true}, {}, {}, 0});
    for (int s = 0; s < 4; ++s) {
      expected.push_back({Kind::set_mux, Mux::sense, {static_cast<std::uint8_t>(s), true}, {}, {}, 0});
      expected.push_back({Kind::wait, {}, {}, {}, {}, s == 0 ? 150u : 25u});
      for (int k = 0; k < 3; ++k) expected.push_back({Kind::read_adc, {}, {}, {}, {}, 0});
    }
  }
  expected.push_back({Kind::set_mux, Mux::ground, {0, false}, {}, {}, 0});
  expected.push_back({Kind::set_mux, Mux::sense, {0, false}, {}, {}, 0});
  ASSERT_EQ(board.events.size(), expected.size());
  for (std::size_t i = 0; i < expected.size(); ++i) {
    const auto& got = board.events[i];
    const auto& want = expected[i];
    ASSERT_EQ(got.kind, want.kind) << "event " << i;
    if (want.kind == Kind::set_mux) {
      EXPECT_EQ(got.mux, want.mux) << "event " << i;
      EXPECT_EQ(got.control, want.control) << "event " << i;
    }
    if (want.kind == Kind::wait || want.kind == Kind::micros) {
      EXPECT_EQ(got.value, want.value) << "event " << i;
    }
  }
  // Total settling: 4 long waits + 12 short ones = 4·150 + 12·25 = 900 µs.
  EXPECT_EQ(board.clock_us, 1000u + 900u);
}

TEST(FirmwareScan, OversampledReadingsAveragedRoundingHalfUp) {
  // (sum + n/2) / n: 100,101,102,103 → 406/4 = 101.5 → 102; 7,8 → 7.5 → 8; 10,10,11 → 10.33 → 10;
  // 10,11,11 → 10.67 → 11.
  struct Case {
    std::vector<std::uint16_t> readings;
    std::uint16_t mean;
  };
  for (const Case& c : {Case{{100, 101, 102, 103}, 102}, Case{{7, 8}, 8}, Case{{10, 10, 11}, 10},
                        Case{{10, 11, 11}, 11}, Case{{4095}, 4095}}) {
    FakeBoard board;
    board.adc = [&](int, int, int k) { return c.readings[static_cast<std::size_t>(k)]; };
    Scanner scanner(options_n(2, static_cast<int>(c.readings.size())));
    ASSERT_TRUE(scanner.scan(board));
    for (int i = 0; i < 4; ++i) EXPECT_EQ(scanner.counts()[i], c.mean) << c.readings.size();
  }
}

TEST(FirmwareScan, MaximumOversamplingOfFullScaleDoesNotOverflow) {
  // 255 readings of 65535 sum to 16,711,425 < 2^32: the mean is exact.
  FakeBoard board;
  board.adc = [](int, int, int) { return std::uint16_t{65535}; };
  ScanOptions options = options_n(2, 255);
  options.adc_bits = 16;
  Scanner scanner(options);
  ASSERT_TRUE(scanner.scan(board));
  EXPECT_EQ(scanner.counts()[3], 65535);
}

TEST(FirmwareScan, HeaderCarriesSequenceTimestampAndSettings) {
  FakeBoard board;
  Scanner scanner(options_n(16, 4));
  for (std::uint32_t frame = 0; frame < 3; ++frame) {
    const std::uint32_t start = board.clock_us;
    ASSERT_TRUE(scanner.scan(board));
    EXPECT_EQ(scanner.header().sequence, frame);
    EXPECT_EQ(scanner.header().timestamp_us, start);  // the clock when the scan started
    EXPECT_EQ(scanner.header().electrode_count, 16);
    EXPECT_EQ(scanner.header().adc_bits, 12);
    EXPECT_EQ(scanner.header().oversampling, 4);
  }
}

TEST(FirmwareScan, ScanAndSendWritesOnePacket) {
  FakeBoard board;
  Scanner scanner(options_n(16));
  EXPECT_EQ(scanner.scan_and_send(board), 532u);  // 16 + 2·256 + 4
  EXPECT_EQ(scanner.scan_and_send(board), 532u);
  ASSERT_EQ(board.written.size(), 1064u);
  EXPECT_EQ(board.written[532], 0x45);  // the second packet's sync
  EXPECT_EQ(board.written[533], 0x4D);
  EXPECT_EQ(board.written[532 + 8], 1);  // its sequence number, low byte
}

TEST(FirmwareScan, InvalidOptionsNamedAndBoardUntouched) {
  struct Case {
    ScanOptions options;
    std::string names;
  };
  std::vector<Case> cases;
  cases.push_back({options_n(1), "electrode_count"});
  cases.push_back({options_n(17), "electrode_count"});  // more than one ADG726's 16 channels
  cases.push_back({options_n(16, 0), "oversampling"});
  cases.push_back({options_n(16, 256), "oversampling"});
  ScanOptions bits = options_n(16);
  bits.adc_bits = 0;
  cases.push_back({bits, "adc_bits"});
  bits.adc_bits = 17;
  cases.push_back({bits, "adc_bits"});
  ScanOptions settle = options_n(16);
  settle.settle_after_sense_us = settle.settle_after_ground_us + 1;
  cases.push_back({settle, "settle_after_sense_us"});
  ScanOptions repeated = options_n(4);
  repeated.channel_of_electrode[3] = 0;  // electrode 0's channel again
  cases.push_back({repeated, "distinct"});
  ScanOptions out_of_range = options_n(4);
  out_of_range.channel_of_electrode[2] = 16;
  cases.push_back({out_of_range, "0..15"});
  for (const Case& c : cases) {
    Scanner scanner(c.options);
    ASSERT_NE(scanner.error(), nullptr) << c.names;
    EXPECT_NE(std::string(scanner.error()).find(c.names), std::string::npos) << scanner.error();
    FakeBoard board;
    EXPECT_FALSE(scanner.scan(board));
    EXPECT_EQ(scanner.scan_and_send(board), 0u);
    EXPECT_TRUE(board.events.empty()) << c.names;
  }
  // Entries beyond electrode_count are not used, so not checked.
  ScanOptions unused = options_n(4);
  unused.channel_of_electrode[10] = 0;
  EXPECT_EQ(firmware::scan_options_error(unused), nullptr);
}

}  // namespace
}  // namespace emit
