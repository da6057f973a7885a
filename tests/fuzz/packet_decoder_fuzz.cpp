// libFuzzer target for the packet decoder: any bytes, fed in pieces whose lengths the input itself
// chooses, must never crash or read out of bounds (ASan, UBSan), and must satisfy:
//   - at most one frame per packet_min_size (28) bytes of input;
//   - each frame has N·N counts, N in 2..64, every count < 2^bits;
//   - splitting changes nothing: the same frames and the same stats as feeding all at once;
//   - stats add up: garbage bytes + 2 · corrupt ≤ input size, frames = the frames delivered.
#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <span>
#include <vector>

#include "core/frame_packet.hpp"
#include "emit/acquire/packet_decoder.hpp"

namespace {

void check(bool condition) {
  if (!condition) std::abort();
}

struct Seen {
  std::vector<std::uint32_t> sequences;
  std::uint64_t count_sum = 0;
};

void check_frame(const emit::RawFrame& frame, Seen& seen) {
  const int n = frame.electrode_count;
  check(n >= emit::firmware::packet_min_electrodes && n <= emit::firmware::packet_max_electrodes);
  check(frame.counts.size() == static_cast<std::size_t>(n) * static_cast<std::size_t>(n));
  check(frame.adc_bits >= 1 && frame.adc_bits <= 16 && frame.oversampling >= 1);
  for (std::uint16_t count : frame.counts) {
    check(count < (1u << frame.adc_bits));
    seen.count_sum += count;
  }
  seen.sequences.push_back(frame.sequence);
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::span<const std::uint8_t> bytes(data, size);

  emit::PacketDecoder whole;
  Seen seen_whole;
  whole.feed(bytes, [&](const emit::RawFrame& frame) { check_frame(frame, seen_whole); });

  // Piece lengths 1..64 taken from the input's own bytes, cycling.
  emit::PacketDecoder pieces;
  Seen seen_pieces;
  std::size_t at = 0;
  for (std::size_t k = 0; at < size; ++k) {
    const std::size_t piece = std::min<std::size_t>(1 + data[k % size] % 64, size - at);
    pieces.feed(bytes.subspan(at, piece), [&](const emit::RawFrame& frame) { check_frame(frame, seen_pieces); });
    at += piece;
  }

  const emit::DecoderStats& a = whole.stats();
  const emit::DecoderStats& b = pieces.stats();
  check(a.frames == seen_whole.sequences.size());
  check(a.frames <= size / emit::firmware::packet_min_size);
  check(a.garbage_bytes + 2 * a.corrupt <= size);
  check(a.frames == b.frames && a.corrupt == b.corrupt && a.dropped == b.dropped && a.garbage_bytes == b.garbage_bytes);
  check(seen_whole.sequences == seen_pieces.sequences && seen_whole.count_sum == seen_pieces.count_sum);
  return 0;
}
