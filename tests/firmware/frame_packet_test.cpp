// The packet encoder and CRC-32 of the firmware core against the documented layout, and the CRC
// against zlib's independent implementation.
#include <gtest/gtest.h>
#include <zlib.h>

#include <numeric>
#include <random>
#include <vector>

#include "core/frame_packet.hpp"

namespace emit {
namespace {

namespace fw = emit::firmware;

std::uint32_t zlib_crc(const std::uint8_t* bytes, std::size_t count) {
  return static_cast<std::uint32_t>(::crc32(0L, bytes, static_cast<uInt>(count)));
}

TEST(FramePacket, Crc32CheckValue) {
  // The CRC-32/ISO-HDLC catalogue's check value: crc("123456789") = 0xCBF43926.
  const std::string check = "123456789";
  EXPECT_EQ(fw::crc32(reinterpret_cast<const std::uint8_t*>(check.data()), check.size()), 0xCBF43926u);
  EXPECT_EQ(fw::crc32(nullptr, 0), 0u);  // empty input: init and final xor cancel
}

TEST(FramePacket, Crc32MatchesZlibAndContinuesOverSplits) {
  std::mt19937 rng(7);
  std::vector<std::uint8_t> bytes(5000);
  for (auto& b : bytes) b = static_cast<std::uint8_t>(rng());
  for (std::size_t length : {1u, 2u, 17u, 532u, 5000u}) {
    EXPECT_EQ(fw::crc32(bytes.data(), length), zlib_crc(bytes.data(), length)) << length;
    const std::size_t half = length / 2;  // a running CRC over two pieces equals the whole one
    EXPECT_EQ(fw::crc32(bytes.data() + half, length - half, fw::crc32(bytes.data(), half)),
              zlib_crc(bytes.data(), length));
  }
}

TEST(FramePacket, SizesOfTheDocumentedLayout) {
  EXPECT_EQ(fw::packet_size(2), 28u);     // 16 + 2·4 + 4
  EXPECT_EQ(fw::packet_size(16), 532u);   // 16 + 2·256 + 4
  EXPECT_EQ(fw::packet_size(64), 8212u);  // 16 + 2·4096 + 4
}

TEST(FramePacket, EncodedBytesAreTheDocumentedFields) {
  fw::PacketHeader header;
  header.electrode_count = 16;
  header.adc_bits = 12;
  header.oversampling = 4;
  header.sequence = 0x12345678;
  header.timestamp_us = 0xA1B2C3D4;
  std::vector<std::uint16_t> counts(256);
  std::iota(counts.begin(), counts.end(), std::uint16_t{3840});  // 0x0F00, 0x0F01, ...
  std::vector<std::uint8_t> packet(600, 0xEE);
  ASSERT_EQ(fw::encode_packet(header, counts.data(), packet.data(), packet.size()), 532u);
  const std::vector<std::uint8_t> head(packet.begin(), packet.begin() + 16);
  const std::vector<std::uint8_t> expected_head = {
      0x45, 0x4D,              // sync "EM"
      1,    16,   12,   4,     // version, N, ADC bits, oversampling
      0x00, 0x02,              // payload length 512, little-endian
      0x78, 0x56, 0x34, 0x12,  // sequence
      0xD4, 0xC3, 0xB2, 0xA1,  // timestamp
  };
  EXPECT_EQ(head, expected_head);
  // Payload: value [g·N + s] at 16 + 2·(g·N + s), little-endian; e.g. g = 2, s = 5 → index 37.
  EXPECT_EQ(packet[16 + 2 * 37], (3840 + 37) & 0xFF);
  EXPECT_EQ(packet[16 + 2 * 37 + 1], (3840 + 37) >> 8);
  EXPECT_EQ(packet[16 + 2 * 255 + 1], (3840 + 255) >> 8);
  // CRC over bytes 2 … 527 (after the sync, through the payload), zlib's, little-endian at 528.
  const std::uint32_t crc = zlib_crc(packet.data() + 2, 526);
  EXPECT_EQ(packet[528], crc & 0xFF);
  EXPECT_EQ(packet[529], (crc >> 8) & 0xFF);
  EXPECT_EQ(packet[530], (crc >> 16) & 0xFF);
  EXPECT_EQ(packet[531], crc >> 24);
  EXPECT_EQ(packet[532], 0xEE);  // nothing written past the packet
}

TEST(FramePacket, RefusesInvalidHeaderOrSmallBuffer) {
  fw::PacketHeader header;
  header.electrode_count = 4;
  header.adc_bits = 12;
  header.oversampling = 1;
  const std::vector<std::uint16_t> counts(16, 7);
  std::vector<std::uint8_t> packet(fw::packet_size(4), 0xEE);
  EXPECT_EQ(fw::encode_packet(header, counts.data(), packet.data(), packet.size() - 1), 0u);
  EXPECT_EQ(packet[0], 0xEE);  // nothing written
  EXPECT_EQ(fw::encode_packet(header, counts.data(), packet.data(), packet.size()), 52u);
  for (auto broken :
       {fw::PacketHeader{1, 12, 1, 0, 0}, fw::PacketHeader{65, 12, 1, 0, 0}, fw::PacketHeader{4, 0, 1, 0, 0},
        fw::PacketHeader{4, 17, 1, 0, 0}, fw::PacketHeader{4, 12, 0, 0, 0}})
    EXPECT_EQ(fw::encode_packet(broken, counts.data(), packet.data(), packet.size()), 0u);
}

}  // namespace
}  // namespace emit
