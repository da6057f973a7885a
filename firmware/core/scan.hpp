#pragma once
/// \file scan.hpp
/// The scan sequencer: one frame is N×N ADC readings, electrode s sensed while electrode g is
/// grounded, for every g then every s (ground-major, the packet's payload order).
///
/// For each grounded electrode g: the ground multiplexer is addressed to g's channel; then for each
/// sensed electrode s: the sense multiplexer is addressed to s's channel, the core waits the
/// settling delay (settle_after_ground_us for the first s after g changed, settle_after_sense_us
/// otherwise), takes `oversampling` ADC readings and stores their mean rounded half up,
/// (sum + oversampling/2) / oversampling, e.g. 100,101,102,103 → 406/4 = 101.5 → 102. At the end
/// of the scan both multiplexers are disabled (/EN high: no electrode grounded between frames, so no
/// current flows through a pressed contact while the frame is sent).
///
/// Example (the ESP32 loop):
///
///     emit::firmware::Scanner scanner(options);   // options checked: scanner.error()
///     for (;;) scanner.scan_and_send(board);      // scan, encode, write one packet
#include <array>
#include <cstddef>
#include <cstdint>

#include "board.hpp"
#include "frame_packet.hpp"

namespace emit::firmware {

/// The most electrodes one scan can address: one ADG726 channel per electrode.
constexpr int scan_max_electrodes = mux_channel_count;

struct ScanOptions {
  /// N, electrodes on the sheet's border, 2..16 (the ADG726 has 16 channels).
  int electrode_count = 16;
  /// ADC resolution reported in the packet, 1..16 (ESP32: 12). Readings are stored as returned.
  int adc_bits = 12;
  /// ADC readings averaged into each value, 1..255.
  int oversampling = 4;
  /// Wait after the grounded electrode changed, µs: the whole sheet's potential moves.
  std::uint32_t settle_after_ground_us = 100;
  /// Wait after only the sensed electrode changed, µs: the ADC input (mux and pin capacitance)
  /// charges through the sheet. Must not exceed settle_after_ground_us.
  std::uint32_t settle_after_sense_us = 20;
  /// Multiplexer address (0..15, channel S1..S16) of electrode e, for e < electrode_count; the same
  /// for both multiplexers. Distinct. Identity by default: electrode e on S(e+1).
  std::array<std::uint8_t, scan_max_electrodes> channel_of_electrode = {
      0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14, 15};
};

/// nullptr if the options are usable, else a one-line message naming the wrong option.
const char* scan_options_error(const ScanOptions& options);

/// Scans frames and encodes them; owns its frame and packet buffers (no heap).
class Scanner {
 public:
  /// Keeps a copy of `options`; if they are invalid, error() says why and scan() does nothing.
  explicit Scanner(const ScanOptions& options);

  /// nullptr if the options were valid, else the message of scan_options_error.
  const char* error() const { return error_; }

  /// Scan one frame on `board`: header() gets the next sequence number and the scan's start time,
  /// counts() the N·N averaged readings. \return false (board untouched) if the options are invalid.
  bool scan(Board& board);

  /// The last scanned frame's header and its N·N values, ground-major.
  const PacketHeader& header() const { return header_; }
  const std::uint16_t* counts() const { return counts_.data(); }

  /// Encode the last scanned frame into `out`. \return its length, 0 if `out` is too small.
  std::size_t encode(std::uint8_t* out, std::size_t capacity) const;

  /// scan(), encode into the scanner's own buffer, write the packet to the board.
  /// \return the bytes written (packet_size(N)), 0 if the options are invalid.
  std::size_t scan_and_send(Board& board);

 private:
  std::uint16_t read_averaged(Board& board) const;

  ScanOptions options_;
  const char* error_ = nullptr;
  std::uint32_t next_sequence_ = 0;
  PacketHeader header_;
  std::array<std::uint16_t, scan_max_electrodes * scan_max_electrodes> counts_{};
  std::array<std::uint8_t, packet_size(scan_max_electrodes)> packet_{};
};

}  // namespace emit::firmware
