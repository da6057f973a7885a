#include "frame_packet.hpp"

#include <array>

namespace emit::firmware {
namespace {

/// The 256-entry table of the reflected polynomial 0xEDB88320, computed at compile time.
constexpr std::array<std::uint32_t, 256> make_crc_table() {
  std::array<std::uint32_t, 256> table{};
  for (std::uint32_t n = 0; n < 256; ++n) {
    std::uint32_t c = n;
    for (int k = 0; k < 8; ++k) c = (c & 1u) ? 0xEDB88320u ^ (c >> 1) : c >> 1;
    table[n] = c;
  }
  return table;
}
constexpr std::array<std::uint32_t, 256> crc_table = make_crc_table();

}  // namespace

bool packet_header_valid(const PacketHeader& header) {
  return header.electrode_count >= packet_min_electrodes &&
         header.electrode_count <= packet_max_electrodes && header.adc_bits >= 1 &&
         header.adc_bits <= packet_max_adc_bits && header.oversampling >= 1;
}

std::uint32_t crc32(const std::uint8_t* bytes, std::size_t count, std::uint32_t crc) {
  crc = ~crc;
  for (std::size_t i = 0; i < count; ++i) crc = crc_table[(crc ^ bytes[i]) & 0xFFu] ^ (crc >> 8);
  return ~crc;
}

std::size_t encode_packet(const PacketHeader& header, const std::uint16_t* counts,
                          std::uint8_t* out, std::size_t out_capacity) {
  if (!packet_header_valid(header) || counts == nullptr || out == nullptr) return 0;
  const int n = header.electrode_count;
  const std::size_t size = packet_size(n);
  if (out_capacity < size) return 0;
  const std::size_t values = static_cast<std::size_t>(n) * static_cast<std::size_t>(n);
  out[0] = packet_sync0;
  out[1] = packet_sync1;
  out[2] = packet_version;
  out[3] = header.electrode_count;
  out[4] = header.adc_bits;
  out[5] = header.oversampling;
  store_u16_le(out + 6, static_cast<std::uint16_t>(2 * values));
  store_u32_le(out + 8, header.sequence);
  store_u32_le(out + 12, header.timestamp_us);
  std::uint8_t* payload = out + packet_header_size;
  for (std::size_t i = 0; i < values; ++i) store_u16_le(payload + 2 * i, counts[i]);
  const std::size_t crc_offset = packet_header_size + 2 * values;
  store_u32_le(out + crc_offset, crc32(out + 2, crc_offset - 2));
  return size;
}

}  // namespace emit::firmware
