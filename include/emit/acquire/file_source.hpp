#pragma once
/// \file file_source.hpp
/// Frames replayed from a recording (recording.hpp; spec "file:PATH"), at the pace the board took
/// them (from the packets' timestamps) or as fast as the caller asks for them; once, or in a loop.
///
/// The file is checked when opened (header, the sensor's electrode count) and each packet (CRC
/// and all) as it is read. A file cut mid-packet (a crashed run's PATH.partial) replays its whole
/// frames, then fails naming the cut: "rec.emitrec: truncated: frame 9 (byte 4820) has 432 of its
/// 532 bytes" (in a loop, at the first pass's cut). A failure is never finished(): the reader
/// asks again and gets it. Counts become volts with the recording's own ADC reference voltage
/// (its header), so a replay gives the volts the live run saw.
///
/// In a loop, the recording starts again after its last frame as if the board had gone on: each
/// pass's sequence numbers follow the last one handed out (+1) and its timestamps the last one by
/// the recording's mean frame interval, so a reader sees one increasing stream (no gap, no step
/// back) for as long as it reads; the raw packet carries the same numbers (a recording of a loop
/// is a longer recording, not the same one again).
///
/// Example:
///
///     emit::FileSource source("rec.bin", sensor, /*as_fast_as_possible=*/false);
///     emit::SourceFrame frame;
///     try {
///       for (;;) if (source.next(frame, std::chrono::milliseconds(100))) use(frame);
///     } catch (const emit::IoError&) { /* end of recording: source.finished() */ }
#include <cstdint>
#include <fstream>
#include <string>
#include <vector>

#include "emit/acquire/board_clock.hpp"
#include "emit/acquire/frame_source.hpp"
#include "emit/acquire/packet_decoder.hpp"
#include "emit/acquire/recording.hpp"

namespace emit {

class FileSource : public FrameSource {
 public:
  /// \param as_fast_as_possible  true: every next() returns the next frame at once (SourceOptions::
  ///   frames_per_s == 0); false: frame k is due (t_k − t_0) after the first was handed out, t the
  ///   board's unwrapped timestamps (board_clock.hpp).
  /// \throw IoError if the file cannot be opened; InvalidInput naming it if it is not a recording
  ///   or was recorded with another electrode count than the sensor's.
  /// \param loop  false: the recording once, then "end of recording"; true: again and again.
  FileSource(std::string path, const Sensor& sensor, bool as_fast_as_possible, bool loop = false);

  /// received: when the frame was handed out. finished() turns true as the last frame is handed
  /// out (never, in a loop, unless the recording has no frames; never for a file cut mid-packet).
  /// \throw IoError "PATH: end of recording" when asked for more, or naming the packet if one is
  ///   corrupt or cut (file's comment).
  bool next(SourceFrame& frame, std::chrono::milliseconds timeout) override;
  bool finished() const override { return finished_; }
  std::string description() const override;

  const RecordingHeader& header() const { return header_; }
  std::uint64_t frame_count() const { return frame_count_; }  ///< whole frames in the file (one pass)
  std::uint64_t passes() const { return pass_; }              ///< completed passes through the file

 private:
  /// Read and decode the next packet into pending_. \return false at the end of the file (in a
  /// loop: only if it has no frames).
  bool read_pending();
  /// Back to the first packet, with the offsets that continue the numbers after the last frame.
  void rewind();

  std::string path_;
  bool as_fast_as_possible_;
  bool loop_;
  std::ifstream stream_;
  RecordingHeader header_;
  std::uint64_t frame_count_ = 0, frames_read_ = 0;
  std::uint64_t cut_bytes_ = 0;  ///< of a last packet cut short (0: the file ends on a whole packet)
  // The loop's continuation (all 0 on the first pass): added to each packet's sequence number and
  // timestamp, modulo 2^32 as the board's own counters wrap.
  std::uint64_t pass_ = 0;
  std::uint32_t sequence_offset_ = 0, timestamp_offset_us_ = 0;
  std::uint32_t first_sequence_ = 0, first_timestamp_us_ = 0;  ///< the file's first packet's
  std::uint32_t last_sequence_ = 0, last_timestamp_us_ = 0;    ///< the last packet handed on, offsets applied
  double first_board_time_s_ = 0, last_board_time_s_ = 0;      ///< the first pass's first frame's, the last one's
  std::uint32_t loop_interval_us_ = 0;                         ///< from one pass's last frame to the next one's first
  std::vector<std::uint8_t> packet_;
  PacketDecoder decoder_;
  BoardClock clock_;
  SourceFrame pending_;
  bool have_pending_ = false;
  bool started_ = false;  ///< the first frame was handed out at start_ with board time t0_s_
  std::chrono::steady_clock::time_point start_;
  double t0_s_ = 0;
  bool finished_ = false;
};

}  // namespace emit
