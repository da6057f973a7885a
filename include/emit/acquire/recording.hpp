#pragma once
/// \file recording.hpp
/// The recording format (docs/recording.md: a compact binary recording with timestamps): a 32-byte file
/// header, then the board's packets v1 (firmware/core/frame_packet.hpp) back to back, verbatim, so
/// each frame keeps its sequence number, board timestamp and CRC. All integers little-endian.
///
///   offset  size  field
///   0       8     magic "EMITREC1"
///   8       2     format version = 1
///   10      2     header size in bytes = 32: the first packet starts here
///   12      2     electrode count N: every packet has this N (and is 20 + 2·N² bytes long)
///   14      2     ADC bits the recording's sensor reads with (the packets carry their own)
///   16      8     ADC reference voltage [V], IEEE-754 double: volts = counts / (2^bits − 1) · vref
///   24      8     when recording started, µs since the Unix epoch (u64; for people, not replay)
///   32      …     packets v1, each packet_size(N) bytes
///
/// A file whose length after the header is not a whole number of packets is truncated (docs/
/// recording.md). Recorder writes it (recorder.hpp), FileSource replays it (file_source.hpp).
#include <cstddef>
#include <cstdint>
#include <string>

namespace emit {

constexpr char recording_magic[8] = {'E', 'M', 'I', 'T', 'R', 'E', 'C', '1'};
constexpr std::uint16_t recording_version = 1;
constexpr std::size_t recording_header_size = 32;

/// The fields of a recording's file header.
struct RecordingHeader {
  int electrode_count = 0;  ///< N, 2..64
  int adc_bits = 0;         ///< 1..16
  double vref_V = 0;        ///< > 0
  std::uint64_t start_unix_us = 0;
};

/// The 32 header bytes of `header` into `out`.
void encode_recording_header(const RecordingHeader& header, std::uint8_t* out);

/// The header from a file's first 32 bytes. \throw InvalidInput naming `path` if it is not an emit
/// recording (magic), has another version or header size, or impossible fields.
RecordingHeader decode_recording_header(const std::uint8_t* bytes, const std::string& path);

}  // namespace emit
