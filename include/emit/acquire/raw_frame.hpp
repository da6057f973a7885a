#pragma once
/// \file raw_frame.hpp
/// A frame as the board sent it: its packet's header fields and the ADC's counts (firmware/
/// README.md, packet v1). The decoder makes them from bytes (packet_decoder.hpp), every source
/// hands one out beside the volts (frame_source.hpp), and a recording stores them verbatim
/// (recorder.hpp).
#include <cstdint>
#include <vector>

namespace emit {

struct RawFrame {
  std::uint32_t sequence = 0;         ///< the board's frame counter (+1 per frame, wraps)
  std::uint32_t timestamp_us = 0;     ///< board clock when the frame's scan started, µs (wraps)
  int electrode_count = 0;            ///< N
  int adc_bits = 0;                   ///< ADC resolution: counts are in 0..2^bits − 1
  int oversampling = 0;               ///< readings the board averaged into each count
  std::vector<std::uint16_t> counts;  ///< N·N ADC counts, ground-major: [g·N + s]
};

}  // namespace emit
