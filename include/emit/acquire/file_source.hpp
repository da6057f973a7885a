#pragma once
/// \file file_source.hpp
/// Frames replayed from a recording (recording.hpp; spec "file:PATH"), at the pace the board took
/// them (from the packets' timestamps) or as fast as the caller asks for them.
///
/// The file is checked when opened (header, the sensor's electrode count, a whole number of
/// packets) and each packet (CRC and all) as it is read. Counts become volts with the recording's
/// own ADC reference voltage (its header), so a replay gives the volts the live run saw.
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
  /// \throw IoError if the file cannot be opened; InvalidInput naming it if it is not a recording,
  ///   is truncated, or was recorded with another electrode count than the sensor's.
  FileSource(std::string path, const Sensor& sensor, bool as_fast_as_possible);

  /// received: when the frame was handed out. finished() turns true as the last frame is handed
  /// out. \throw IoError "PATH: end of recording" when asked for more, or naming the packet if one
  /// is corrupt.
  bool next(SourceFrame& frame, std::chrono::milliseconds timeout) override;
  bool finished() const override { return finished_; }
  std::string description() const override;

  const RecordingHeader& header() const { return header_; }

 private:
  /// Read and decode the next packet into pending_. \return false at the end of the file.
  bool read_pending();

  std::string path_;
  bool as_fast_as_possible_;
  std::ifstream stream_;
  RecordingHeader header_;
  std::uint64_t frame_count_ = 0, frames_read_ = 0;
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
