#pragma once
/// \file frame_packet.hpp
/// The serial frame packet, version 1: how one frame of N×N ADC readings crosses the USB-UART.
/// All integers little-endian.
///
///   offset        size  field
///   0             2     sync 0x45 0x4D ("EM")
///   2             1     version = 1
///   3             1     electrode count N, 2..64
///   4             1     ADC bits, 1..16 (the ESP32: 12)
///   5             1     oversampling: ADC readings averaged into each value, 1..255
///   6             2     payload length in bytes = 2·N·N (u16; redundant with N on purpose, a check)
///   8             4     sequence number (u32, +1 per frame, wraps)
///   12            4     timestamp, µs of the board's clock when the frame's scan started (u32, wraps)
///   16            2·N²  payload: N·N u16 ADC counts, averaged over the oversampling, each in
///                       0..2^bits − 1; ground-major: value [g·N + s] is electrode s sensed while
///                       electrode g is grounded
///   16 + 2·N²     4     CRC-32 (IEEE 802.3 / zlib: polynomial 0xEDB88320 reflected, init and final
///                       xor 0xFFFFFFFF) over bytes 2 … end of payload (everything after the sync)
///
/// A packet is 20 + 2·N² bytes: 532 for N = 16.
#include <cstddef>
#include <cstdint>

namespace emit::firmware {

constexpr std::uint8_t packet_sync0 = 0x45;  // 'E'
constexpr std::uint8_t packet_sync1 = 0x4D;  // 'M'
constexpr std::uint8_t packet_version = 1;
constexpr std::size_t packet_header_size = 16;
constexpr std::size_t packet_crc_size = 4;
constexpr int packet_min_electrodes = 2;
constexpr int packet_max_electrodes = 64;
constexpr int packet_max_adc_bits = 16;

/// Bytes of a packet carrying N×N values: header + 2·N² + CRC.
constexpr std::size_t packet_size(int electrode_count) {
  return packet_header_size + 2 * static_cast<std::size_t>(electrode_count) *
                                  static_cast<std::size_t>(electrode_count) +
         packet_crc_size;
}
constexpr std::size_t packet_min_size = packet_size(packet_min_electrodes);  // 28
constexpr std::size_t packet_max_size = packet_size(packet_max_electrodes);  // 8212

/// Everything in a packet but the payload.
struct PacketHeader {
  std::uint8_t electrode_count = 0;  ///< N
  std::uint8_t adc_bits = 0;
  std::uint8_t oversampling = 0;
  std::uint32_t sequence = 0;
  std::uint32_t timestamp_us = 0;
};

/// Whether a header's fields are in the ranges above (N in 2..64, bits in 1..16, oversampling ≥ 1).
bool packet_header_valid(const PacketHeader& header);

/// CRC-32 of `count` bytes, zlib's crc32(): pass a previous result as `crc` to continue a running
/// CRC over split data (start from 0). Table-driven, the 1 KiB table in flash (constexpr).
std::uint32_t crc32(const std::uint8_t* bytes, std::size_t count, std::uint32_t crc = 0);

/// Encode one frame into `out` (capacity `out_capacity` bytes). `counts` holds N·N values,
/// ground-major. \return the packet length packet_size(N), or 0 (and nothing written) if the
/// header is invalid or the buffer too small. Values are written as given (not clamped).
std::size_t encode_packet(const PacketHeader& header, const std::uint16_t* counts,
                          std::uint8_t* out, std::size_t out_capacity);

/// Little-endian loads and stores, byte by byte (no alignment or host-order assumptions).
inline std::uint16_t load_u16_le(const std::uint8_t* p) {
  return static_cast<std::uint16_t>(p[0] | (p[1] << 8));
}
inline std::uint32_t load_u32_le(const std::uint8_t* p) {
  return static_cast<std::uint32_t>(p[0]) | (static_cast<std::uint32_t>(p[1]) << 8) |
         (static_cast<std::uint32_t>(p[2]) << 16) | (static_cast<std::uint32_t>(p[3]) << 24);
}
inline void store_u16_le(std::uint8_t* p, std::uint16_t v) {
  p[0] = static_cast<std::uint8_t>(v);
  p[1] = static_cast<std::uint8_t>(v >> 8);
}
inline void store_u32_le(std::uint8_t* p, std::uint32_t v) {
  for (int k = 0; k < 4; ++k) p[k] = static_cast<std::uint8_t>(v >> (8 * k));
}

}  // namespace emit::firmware
