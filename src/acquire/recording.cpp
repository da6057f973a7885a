#include "emit/acquire/recording.hpp"

#include <bit>
#include <cmath>
#include <cstring>

#include "core/frame_packet.hpp"
#include "emit/core/errors.hpp"

namespace emit {
namespace fw = emit::firmware;
namespace {

void store_u64_le(std::uint8_t* p, std::uint64_t v) {
  fw::store_u32_le(p, static_cast<std::uint32_t>(v));
  fw::store_u32_le(p + 4, static_cast<std::uint32_t>(v >> 32));
}
std::uint64_t load_u64_le(const std::uint8_t* p) {
  return fw::load_u32_le(p) | (static_cast<std::uint64_t>(fw::load_u32_le(p + 4)) << 32);
}

}  // namespace

void encode_recording_header(const RecordingHeader& header, std::uint8_t* out) {
  std::memcpy(out, recording_magic, sizeof recording_magic);
  fw::store_u16_le(out + 8, recording_version);
  fw::store_u16_le(out + 10, static_cast<std::uint16_t>(recording_header_size));
  fw::store_u16_le(out + 12, static_cast<std::uint16_t>(header.electrode_count));
  fw::store_u16_le(out + 14, static_cast<std::uint16_t>(header.adc_bits));
  store_u64_le(out + 16, std::bit_cast<std::uint64_t>(header.vref_V));
  store_u64_le(out + 24, header.start_unix_us);
}

RecordingHeader decode_recording_header(const std::uint8_t* bytes, const std::string& path) {
  if (std::memcmp(bytes, recording_magic, sizeof recording_magic) != 0)
    throw InvalidInput(path + ": not an emit recording (it does not start with EMITREC1)");
  const int version = fw::load_u16_le(bytes + 8);
  if (version != recording_version)
    throw InvalidInput(path + ": recording format version " + std::to_string(version) + "; this emit reads version 1");
  if (fw::load_u16_le(bytes + 10) != recording_header_size)
    throw InvalidInput(path + ": recording header size " + std::to_string(fw::load_u16_le(bytes + 10)) +
                       " bytes; version 1 has 32");
  RecordingHeader header;
  header.electrode_count = fw::load_u16_le(bytes + 12);
  header.adc_bits = fw::load_u16_le(bytes + 14);
  header.vref_V = std::bit_cast<double>(load_u64_le(bytes + 16));
  header.start_unix_us = load_u64_le(bytes + 24);
  if (header.electrode_count < fw::packet_min_electrodes || header.electrode_count > fw::packet_max_electrodes)
    throw InvalidInput(path + ": recording header: electrode count " + std::to_string(header.electrode_count) +
                       " is outside 2..64");
  if (header.adc_bits < 1 || header.adc_bits > fw::packet_max_adc_bits)
    throw InvalidInput(path + ": recording header: ADC bits " + std::to_string(header.adc_bits) + " outside 1..16");
  if (!std::isfinite(header.vref_V) || header.vref_V <= 0)
    throw InvalidInput(path + ": recording header: the ADC reference voltage is not a positive number");
  return header;
}

}  // namespace emit
