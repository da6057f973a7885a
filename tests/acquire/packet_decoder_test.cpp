// The host packet decoder: clean streams in any split, resynchronisation after garbage with exact
// counts of what is lost, CRC and header checks, sequence gaps with wrap-around, no allocation per
// frame, and the round trip from the firmware core's scanner.
#include "emit/acquire/packet_decoder.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <random>
#include <vector>

#include "allocation_counter.hpp"
#include "core/frame_packet.hpp"
#include "core/scan.hpp"
#include "emit/core/errors.hpp"
#include "fake_board.hpp"

namespace emit {
namespace {

namespace fw = emit::firmware;
using Bytes = std::vector<std::uint8_t>;

/// Counts of frame `sequence`: distinct per frame and position, < 2^12.
std::vector<std::uint16_t> counts_of(int n, std::uint32_t sequence) {
  std::vector<std::uint16_t> counts(static_cast<std::size_t>(n) * static_cast<std::size_t>(n));
  for (std::size_t i = 0; i < counts.size(); ++i)
    counts[i] = static_cast<std::uint16_t>((std::size_t{sequence} * 131 + i * 7) % 4096);
  return counts;
}

Bytes packet(std::uint32_t sequence, int n = 16, std::uint32_t timestamp_us = 0) {
  const fw::PacketHeader header{static_cast<std::uint8_t>(n), 12, 4, sequence,
                                timestamp_us ? timestamp_us : 1000 + 20000 * sequence};
  Bytes bytes(fw::packet_size(n));
  const auto counts = counts_of(n, sequence);
  EXPECT_EQ(fw::encode_packet(header, counts.data(), bytes.data(), bytes.size()), bytes.size());
  return bytes;
}

/// Recompute the CRC of a packet whose header or payload a test changed on purpose.
void reseal(Bytes& bytes) {
  const std::size_t crc_at = bytes.size() - 4;
  fw::store_u32_le(bytes.data() + crc_at, fw::crc32(bytes.data() + 2, crc_at - 2));
}

void append(Bytes& to, const Bytes& bytes) { to.insert(to.end(), bytes.begin(), bytes.end()); }

/// Occurrences of the sync "EM". The tests' exact counts of corrupt packets and garbage bytes
/// assume a sync only where a packet starts; this checks that assumption of their data.
int syncs_in(const Bytes& bytes) {
  int count = 0;
  for (std::size_t i = 0; i + 1 < bytes.size(); ++i)
    count += bytes[i] == fw::packet_sync0 && bytes[i + 1] == fw::packet_sync1;
  return count;
}

/// Garbage without 'E' or 'M', so it cannot form a sync with anything around it.
Bytes garbage(std::size_t count, std::mt19937& rng) {
  Bytes bytes;
  while (bytes.size() < count) {
    const auto b = static_cast<std::uint8_t>(rng());
    if (b != fw::packet_sync0 && b != fw::packet_sync1) bytes.push_back(b);
  }
  return bytes;
}

struct Decoded {
  std::vector<RawFrame> frames;
  DecoderStats stats;
};

/// Decode `stream` fed in random pieces of 1..max_piece bytes.
Decoded decode(const Bytes& stream, std::size_t max_piece = 1200, unsigned seed = 1) {
  PacketDecoder decoder;
  Decoded out;
  std::mt19937 rng(seed);
  std::size_t at = 0;
  while (at < stream.size()) {
    const std::size_t piece = std::min<std::size_t>(1 + rng() % max_piece, stream.size() - at);
    decoder.feed(std::span(stream.data() + at, piece), [&](const RawFrame& frame) { out.frames.push_back(frame); });
    at += piece;
  }
  out.stats = decoder.stats();
  return out;
}

std::vector<std::uint32_t> sequences(const Decoded& decoded) {
  std::vector<std::uint32_t> result;
  for (const RawFrame& frame : decoded.frames) result.push_back(frame.sequence);
  return result;
}

std::vector<std::uint32_t> range(std::uint32_t first, std::uint32_t end) {
  std::vector<std::uint32_t> result;
  for (std::uint32_t s = first; s < end; ++s) result.push_back(s);
  return result;
}

TEST(PacketDecoder, CleanStreamInAnySplitGivesEveryFrameExactly) {
  Bytes stream;
  for (std::uint32_t s = 0; s < 40; ++s) append(stream, packet(s));
  for (std::size_t max_piece : {1u, 7u, 531u, 533u, 1200u, 30000u})  // byte by byte … all at once
    for (unsigned seed = 1; seed <= 3; ++seed) {
      const Decoded decoded = decode(stream, max_piece, seed);
      ASSERT_EQ(decoded.frames.size(), 40u) << max_piece;
      for (std::uint32_t s = 0; s < 40; ++s) {
        const RawFrame& frame = decoded.frames[s];
        EXPECT_EQ(frame.sequence, s);
        EXPECT_EQ(frame.timestamp_us, 1000 + 20000 * s);
        EXPECT_EQ(frame.electrode_count, 16);
        EXPECT_EQ(frame.adc_bits, 12);
        EXPECT_EQ(frame.oversampling, 4);
        EXPECT_EQ(frame.counts, counts_of(16, s));
      }
      EXPECT_EQ(decoded.stats.frames, 40u);
      EXPECT_EQ(decoded.stats.corrupt, 0u);
      EXPECT_EQ(decoded.stats.dropped, 0u);
      EXPECT_EQ(decoded.stats.garbage_bytes, 0u);
    }
}

TEST(PacketDecoder, MixedElectrodeCountsDecode) {
  Bytes stream;
  append(stream, packet(0, 2));
  append(stream, packet(1, 64));
  append(stream, packet(2, 16));
  const Decoded decoded = decode(stream, 100);
  ASSERT_EQ(decoded.frames.size(), 3u);
  EXPECT_EQ(decoded.frames[0].counts.size(), 4u);
  EXPECT_EQ(decoded.frames[1].counts.size(), 4096u);
  EXPECT_EQ(decoded.frames[1].counts, counts_of(64, 1));
  EXPECT_EQ(decoded.frames[2].counts.size(), 256u);
}

TEST(PacketDecoder, GarbageBetweenPacketsIsSkippedAndCounted) {
  std::mt19937 rng(3);
  Bytes stream;
  std::size_t garbage_total = 0;
  for (std::uint32_t s = 0; s < 40; ++s) {
    const Bytes junk = garbage(1 + rng() % 100, rng);
    garbage_total += junk.size();
    append(stream, junk);
    append(stream, packet(s));
  }
  const Bytes tail = garbage(9, rng);
  append(stream, tail);
  garbage_total += tail.size();
  ASSERT_EQ(syncs_in(stream), 40);
  const Decoded decoded = decode(stream);
  EXPECT_EQ(sequences(decoded), range(0, 40));
  EXPECT_EQ(decoded.stats.corrupt, 0u);
  EXPECT_EQ(decoded.stats.dropped, 0u);
  EXPECT_EQ(decoded.stats.garbage_bytes, garbage_total);
}

TEST(PacketDecoder, GarbageInsidePacketsLosesOnlyThosePackets) {
  // Garbage inserted into packet 3's header, packet 17's payload, packet 39's CRC (the last: its
  // loss shows in no later sequence number). Each broken packet is rejected once (corrupt), its
  // bytes after the sync and the inserted garbage are searched again (garbage_bytes), and the next
  // packet is found: 37 frames.
  std::mt19937 rng(5);
  const std::vector<std::pair<std::uint32_t, std::size_t>> breaks = {{3, 5}, {17, 300}, {39, 529}};
  Bytes stream;
  std::size_t garbage_total = 0;
  for (std::uint32_t s = 0; s < 40; ++s) {
    Bytes p = packet(s);
    for (const auto& [broken, offset] : breaks)
      if (s == broken) {
        const Bytes junk = garbage(25, rng);
        p.insert(p.begin() + static_cast<std::ptrdiff_t>(offset), junk.begin(), junk.end());
        garbage_total += junk.size() + 532 - 2;
      }
    append(stream, p);
  }
  ASSERT_EQ(syncs_in(stream), 40);
  for (std::size_t max_piece : {1u, 64u, 1200u}) {
    const Decoded decoded = decode(stream, max_piece);
    std::vector<std::uint32_t> expected = range(0, 40);
    std::erase_if(expected, [](std::uint32_t s) { return s == 3 || s == 17 || s == 39; });
    EXPECT_EQ(sequences(decoded), expected);
    EXPECT_EQ(decoded.stats.frames, 37u);
    EXPECT_EQ(decoded.stats.corrupt, 3u);
    EXPECT_EQ(decoded.stats.dropped, 2u);  // 3 and 17; 39 was the last
    EXPECT_EQ(decoded.stats.garbage_bytes, garbage_total);
  }
}

TEST(PacketDecoder, PacketsHiddenBehindAFakeHeaderAreFound) {
  // A sync in the garbage with a plausible header announcing N = 64 (8,212 bytes): the decoder
  // waits for that many bytes, the CRC fails, and the search resumes right after the fake sync,
  // so the 20 real packets buffered meanwhile are all found.
  Bytes stream = {0x45, 0x4D, 1, 64, 12, 4, 0x00, 0x20, 9, 0, 0, 0, 1, 2, 3, 0};
  for (std::uint32_t s = 0; s < 20; ++s) append(stream, packet(s));
  ASSERT_EQ(syncs_in(stream), 21);
  const Decoded decoded = decode(stream);
  EXPECT_EQ(sequences(decoded), range(0, 20));
  EXPECT_EQ(decoded.stats.corrupt, 1u);
  EXPECT_EQ(decoded.stats.garbage_bytes, 14u);  // the fake header after its sync
}

TEST(PacketDecoder, TruncatedPacketLosesOnlyItself) {
  // The cable pulled mid-packet: packet 5 stops after 300 bytes, packet 6 follows.
  Bytes stream;
  for (std::uint32_t s = 0; s < 10; ++s) {
    Bytes p = packet(s);
    if (s == 5) p.resize(300);
    append(stream, p);
  }
  ASSERT_EQ(syncs_in(stream), 10);
  const Decoded decoded = decode(stream);
  EXPECT_EQ(decoded.stats.frames, 9u);
  EXPECT_EQ(decoded.stats.corrupt, 1u);
  EXPECT_EQ(decoded.stats.dropped, 1u);
  EXPECT_EQ(decoded.stats.garbage_bytes, 298u);
}

TEST(PacketDecoder, FlippedBitIsRejectedByTheCrc) {
  // One bit flipped in packet 4 of 10, in the sequence number, the payload or the CRC itself.
  for (const auto& [byte, bit] :
       std::vector<std::pair<std::size_t, int>>{{8, 0}, {12, 7}, {16, 0}, {100, 3}, {527, 1}, {528, 0}, {531, 7}}) {
    Bytes stream;
    for (std::uint32_t s = 0; s < 10; ++s) {
      Bytes p = packet(s);
      if (s == 4) p[byte] ^= static_cast<std::uint8_t>(1u << bit);
      append(stream, p);
    }
    ASSERT_EQ(syncs_in(stream), 10) << byte;
    const Decoded decoded = decode(stream);
    EXPECT_EQ(decoded.stats.frames, 9u) << byte;
    EXPECT_EQ(decoded.stats.corrupt, 1u) << byte;
    EXPECT_EQ(decoded.stats.dropped, 1u) << byte;
    const auto seen = sequences(decoded);
    EXPECT_EQ(std::count(seen.begin(), seen.end(), 4u), 0) << byte;
  }
}

TEST(PacketDecoder, ImpossibleHeadersRejectedEvenWithAValidCrc) {
  // Each bad packet (CRC recomputed, so only the header or range check can catch it) between two
  // good ones: 2 frames, 1 corrupt.
  std::vector<std::pair<const char*, Bytes>> bad;
  auto with = [](std::size_t at, std::uint8_t value) {
    Bytes p = packet(1, 4);
    p[at] = value;
    reseal(p);
    return p;
  };
  bad.emplace_back("version 2", with(2, 2));
  bad.emplace_back("N = 1", with(3, 1));
  bad.emplace_back("N = 5 with length 32", with(3, 5));
  bad.emplace_back("length 34", with(6, 34));
  bad.emplace_back("0 ADC bits", with(4, 0));
  bad.emplace_back("17 ADC bits", with(4, 17));
  bad.emplace_back("oversampling 0", with(5, 0));
  Bytes high = packet(1, 4);  // a count of 4096 in a 12-bit frame
  fw::store_u16_le(high.data() + 16 + 2 * std::ptrdiff_t{5}, 4096);
  reseal(high);
  bad.emplace_back("count 4096 at 12 bits", high);
  for (const auto& [what, p] : bad) {
    Bytes stream = packet(0, 4);
    append(stream, p);
    append(stream, packet(2, 4));
    ASSERT_EQ(syncs_in(stream), 3) << what;
    const Decoded decoded = decode(stream);
    EXPECT_EQ(sequences(decoded), (std::vector<std::uint32_t>{0, 2})) << what;
    EXPECT_EQ(decoded.stats.corrupt, 1u) << what;
    EXPECT_EQ(decoded.stats.dropped, 1u) << what;
  }
}

Decoded decode_sequence(const std::vector<std::uint32_t>& numbers) {
  Bytes stream;
  for (std::uint32_t s : numbers) append(stream, packet(s, 2, 1));
  return decode(stream);
}

TEST(PacketDecoder, SequenceGapsCountAsDropped) {
  // 0,1,2,5,6,10: 3 and 4 missing, then 7, 8, 9: 5 dropped.
  const Decoded decoded = decode_sequence({0, 1, 2, 5, 6, 10});
  EXPECT_EQ(decoded.stats.frames, 6u);
  EXPECT_EQ(decoded.stats.dropped, 5u);
  EXPECT_EQ(decoded.stats.corrupt, 0u);
}

TEST(PacketDecoder, SequenceWrapsAround) {
  EXPECT_EQ(decode_sequence({0xFFFFFFFE, 0xFFFFFFFF, 0, 1}).stats.dropped, 0u);
  // 0xFFFFFFFF then 2: 0 and 1 missing across the wrap.
  EXPECT_EQ(decode_sequence({0xFFFFFFFE, 0xFFFFFFFF, 2}).stats.dropped, 2u);
}

TEST(PacketDecoder, BoardRestartIsNotCountedAsDrops) {
  // Back to 0 (the board reset) or the same number again: nothing dropped, counting restarts there.
  EXPECT_EQ(decode_sequence({100, 101, 0, 1, 3}).stats.dropped, 1u);
  EXPECT_EQ(decode_sequence({5, 5, 6}).stats.dropped, 0u);
}

TEST(PacketDecoder, RestartStreamForgetsHalfPacketAndSequence) {
  PacketDecoder decoder;
  std::vector<std::uint32_t> seen;
  auto keep = [&](const RawFrame& frame) { seen.push_back(frame.sequence); };
  const Bytes first = packet(0);
  decoder.feed(std::span(first.data(), 300), keep);  // the cable is pulled here
  decoder.restart_stream();
  for (std::uint32_t s : {7u, 8u}) decoder.feed(packet(s), keep);
  EXPECT_EQ(seen, (std::vector<std::uint32_t>{7, 8}));
  EXPECT_EQ(decoder.stats().corrupt, 0u);
  EXPECT_EQ(decoder.stats().dropped, 0u);  // 0 → 7 is a new stream, not a gap
  EXPECT_EQ(decoder.stats().garbage_bytes, 0u);
}

TEST(PacketDecoder, RandomBytesNeverDecodeAndNeverCrash) {
  // 1 MB of noise: a packet needs "EM", a valid header and a matching 32-bit CRC, so none appears
  // (the chance of a false one is below 1e-6 here).
  std::mt19937 rng(11);
  Bytes noise(1 << 20);
  for (auto& b : noise) b = static_cast<std::uint8_t>(rng());
  const Decoded decoded = decode(noise, 5000);
  EXPECT_EQ(decoded.stats.frames, 0u);
  // Every byte is garbage, a rejected sync (2 bytes) or still buffered (less than one packet).
  EXPECT_GE(decoded.stats.garbage_bytes + 2 * decoded.stats.corrupt + fw::packet_max_size, noise.size());
  EXPECT_LE(decoded.stats.garbage_bytes + 2 * decoded.stats.corrupt, noise.size());
}

TEST(PacketDecoder, NoAllocationPerFrameOnceWarmedUp) {
  Bytes stream;
  for (std::uint32_t s = 0; s < 20; ++s) append(stream, packet(s));
  PacketDecoder decoder;
  Frame volts(16, 16);
  std::uint64_t total = 0;
  auto use = [&](const RawFrame& frame) {
    to_volts(frame, 3.3, volts);
    total += frame.counts[0];
  };
  decoder.feed(packet(100), use);  // warm-up
  test::AllocationCounter allocations;
  for (std::size_t at = 0; at < stream.size(); at += 97)
    decoder.feed(std::span(stream.data() + at, std::min<std::size_t>(97, stream.size() - at)), use);
  EXPECT_EQ(allocations.count(), 0);
  EXPECT_EQ(decoder.stats().frames, 21u);
  EXPECT_GT(total, 0u);
}

TEST(PacketDecoder, RoundTripFromTheFirmwareScanner) {
  test::FakeBoard board;
  fw::ScanOptions options;  // 16 electrodes, 12 bits, 4 readings a value
  board.adc = [](int g, int s, int k) { return static_cast<std::uint16_t>(200 * g + 10 * s + k); };
  fw::Scanner scanner(options);
  std::vector<std::vector<std::uint16_t>> sent;
  std::vector<std::uint32_t> started;
  for (int frame = 0; frame < 3; ++frame) {
    ASSERT_EQ(scanner.scan_and_send(board), 532u);
    sent.emplace_back(scanner.counts(), scanner.counts() + 256);
    started.push_back(scanner.header().timestamp_us);
  }
  const Decoded decoded = decode(board.written, 50);
  ASSERT_EQ(decoded.frames.size(), 3u);
  for (std::size_t f = 0; f < 3; ++f) {
    EXPECT_EQ(decoded.frames[f].sequence, f);
    EXPECT_EQ(decoded.frames[f].timestamp_us, started[f]);
    EXPECT_EQ(decoded.frames[f].oversampling, 4);
    EXPECT_EQ(decoded.frames[f].counts, sent[f]);
  }
  // g = 2, s = 3: readings 430, 431, 432, 433 → 1726/4 = 431.5 → 432.
  EXPECT_EQ(decoded.frames[0].counts[2 * 16 + 3], 432);
}

TEST(PacketDecoder, ToVoltsScalesCountsToTheReference) {
  RawFrame raw;
  raw.electrode_count = 2;
  raw.adc_bits = 12;
  raw.counts = {0, 4095, 2048, 1};
  const Frame volts = to_volts(raw, 3.3);
  ASSERT_EQ(volts.rows(), 2);
  ASSERT_EQ(volts.cols(), 2);
  EXPECT_EQ(volts(0, 0), 0.0);
  EXPECT_DOUBLE_EQ(volts(0, 1), 3.3);                // full scale = vref
  EXPECT_DOUBLE_EQ(volts(1, 0), 2048 * 3.3 / 4095);  // row g = 1 grounded, column s = 0 sensed
  EXPECT_DOUBLE_EQ(volts(1, 1), 3.3 / 4095);
  EXPECT_THROW(to_volts(raw, 0.0), InvalidInput);
  EXPECT_THROW(to_volts(raw, std::nan("")), InvalidInput);
  raw.counts.pop_back();
  EXPECT_THROW(to_volts(raw, 3.3), InvalidInput);
}

}  // namespace
}  // namespace emit
