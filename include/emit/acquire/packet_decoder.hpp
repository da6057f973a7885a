#pragma once
/// \file packet_decoder.hpp
/// The host side of the board's serial frame protocol (packet v1, firmware/README.md and
/// firmware/core/frame_packet.hpp): bytes in, as they arrive and split anywhere; frames out.
///
/// The decoder finds packets by their sync bytes "EM", checks the header (version 1, N in 2..64,
/// ADC bits in 1..16, oversampling ≥ 1, payload length = 2·N²), the CRC-32 and that every count is
/// below 2^bits. A packet failing any check counts one `corrupt`, and the search resumes at the byte
/// after its sync, so a real packet hidden inside garbage, or starting inside a broken one, is
/// still found. Holds at most one packet's worth of bytes (8,212 at N = 64); never allocates after
/// construction.
///
/// Example:
///
///     emit::PacketDecoder decoder;
///     decoder.feed(bytes_from_serial, [&](const emit::RawFrame& raw) {
///       emit::to_volts(raw, 3.3, volts);   // reuses `volts`
///     });
#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

#include "emit/acquire/raw_frame.hpp"
#include "emit/core/types.hpp"

namespace emit {

/// What the decoder has seen since construction.
struct DecoderStats {
  std::uint64_t frames = 0;  ///< valid packets delivered
  /// Packets rejected after their sync: impossible header, CRC mismatch or a count ≥ 2^bits.
  std::uint64_t corrupt = 0;
  /// Frames missing from the sequence numbers of delivered frames (wrap-around aware): those the
  /// board sent that were lost or corrupt. A sequence number at or behind the previous one (the
  /// board restarted) adds nothing and restarts the count from there.
  std::uint64_t dropped = 0;
  /// Bytes skipped while searching for a sync. The 2 sync bytes of a rejected packet are not
  /// counted; the bytes after them are searched again and counted here if no packet starts there.
  std::uint64_t garbage_bytes = 0;
};

class PacketDecoder {
 public:
  PacketDecoder();

  /// Feed bytes as they arrive (any split, any length); calls on_frame(const RawFrame&) for every
  /// complete valid packet, in order. The RawFrame is the decoder's own: valid until on_frame
  /// returns. Bytes of an incomplete packet are kept for the next call.
  template <class OnFrame>
  void feed(std::span<const std::uint8_t> bytes, OnFrame&& on_frame) {
    while (!bytes.empty()) {
      bytes = bytes.subspan(push(bytes));
      while (const RawFrame* frame = next_frame()) on_frame(*frame);
    }
  }

  const DecoderStats& stats() const { return stats_; }

  /// Forget buffered bytes and the last sequence number (e.g. after the serial port reopened), so
  /// neither a half packet nor the gap counts against the new stream. Keeps the stats.
  void restart_stream();

 private:
  /// Copy as many of `bytes` as fit in the buffer. \return how many. \pre next_frame() returned
  /// nullptr since the last push (then at least one byte fits).
  std::size_t push(std::span<const std::uint8_t> bytes);
  /// The next valid packet in the buffer, consuming it and anything before it; nullptr when the
  /// buffer holds no complete packet.
  const RawFrame* next_frame();
  /// Check the packet at the buffer's start (its sync already found) and decode it into frame_.
  enum class Verdict { need_more, rejected, accepted };
  Verdict try_decode(const std::uint8_t* bytes, std::size_t available, std::size_t* size);
  void count_sequence(std::uint32_t sequence);

  std::vector<std::uint8_t> buffer_;  // packet_max_size bytes; live bytes are [begin_, end_)
  std::size_t begin_ = 0, end_ = 0;
  RawFrame frame_;
  DecoderStats stats_;
  bool have_sequence_ = false;
  std::uint32_t last_sequence_ = 0;
};

/// Counts → volts: counts / (2^bits − 1) · vref_V, as an N×N Frame (row g grounded, column s
/// sensed). \throw InvalidInput if vref_V is not positive and finite, or the frame is malformed
/// (counts.size() ≠ N², bits outside 1..16).
Frame to_volts(const RawFrame& frame, double vref_V);

/// The same into `volts`, resized only if its shape differs (no allocation per frame).
void to_volts(const RawFrame& frame, double vref_V, Frame& volts);

}  // namespace emit
