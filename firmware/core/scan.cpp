#include "scan.hpp"

namespace emit::firmware {

const char* scan_options_error(const ScanOptions& options) {
  if (options.electrode_count < packet_min_electrodes ||
      options.electrode_count > scan_max_electrodes)
    return "electrode_count must be in 2..16 (one ADG726 channel per electrode)";
  if (options.adc_bits < 1 || options.adc_bits > packet_max_adc_bits)
    return "adc_bits must be in 1..16";
  if (options.oversampling < 1 || options.oversampling > 255)
    return "oversampling must be in 1..255";
  if (options.settle_after_sense_us > options.settle_after_ground_us)
    return "settle_after_sense_us must not exceed settle_after_ground_us";
  std::uint32_t used = 0;  // bit c set: channel c taken
  for (int e = 0; e < options.electrode_count; ++e) {
    const std::uint8_t channel = options.channel_of_electrode[static_cast<std::size_t>(e)];
    if (channel >= mux_channel_count) return "channel_of_electrode entries must be in 0..15";
    if (used & (1u << channel)) return "channel_of_electrode entries must be distinct";
    used |= 1u << channel;
  }
  return nullptr;
}

Scanner::Scanner(const ScanOptions& options)
    : options_(options), error_(scan_options_error(options)) {}

std::uint16_t Scanner::read_averaged(Board& board) const {
  const auto n = static_cast<std::uint32_t>(options_.oversampling);
  std::uint32_t sum = 0;  // ≤ 255 · 65535 < 2^32
  for (std::uint32_t k = 0; k < n; ++k) sum += board.read_adc();
  return static_cast<std::uint16_t>((sum + n / 2) / n);
}

bool Scanner::scan(Board& board) {
  if (error_ != nullptr) return false;
  const int n = options_.electrode_count;
  header_.electrode_count = static_cast<std::uint8_t>(n);
  header_.adc_bits = static_cast<std::uint8_t>(options_.adc_bits);
  header_.oversampling = static_cast<std::uint8_t>(options_.oversampling);
  header_.sequence = next_sequence_++;
  header_.timestamp_us = board.micros();
  for (int g = 0; g < n; ++g) {
    board.set_mux(Mux::ground, {options_.channel_of_electrode[static_cast<std::size_t>(g)], true});
    for (int s = 0; s < n; ++s) {
      board.set_mux(Mux::sense, {options_.channel_of_electrode[static_cast<std::size_t>(s)], true});
      board.wait_us(s == 0 ? options_.settle_after_ground_us : options_.settle_after_sense_us);
      counts_[static_cast<std::size_t>(g * n + s)] = read_averaged(board);
    }
  }
  board.set_mux(Mux::ground, {0, false});
  board.set_mux(Mux::sense, {0, false});
  return true;
}

std::size_t Scanner::encode(std::uint8_t* out, std::size_t capacity) const {
  return encode_packet(header_, counts_.data(), out, capacity);
}

std::size_t Scanner::scan_and_send(Board& board) {
  if (!scan(board)) return 0;
  const std::size_t size = encode(packet_.data(), packet_.size());
  board.write(packet_.data(), size);
  return size;
}

}  // namespace emit::firmware
