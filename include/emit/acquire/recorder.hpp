#pragma once
/// \file recorder.hpp
/// Writes a recording (recording.hpp) frame by frame, as frames arrive (`emit live --record`).
///
/// Output goes to PATH.partial and is renamed to PATH by close() (or the destructor), so a crash
/// never leaves a half file over a good one; PATH.partial after a crash holds whole packets up to
/// the last flush and perhaps a cut one at its end. A PATH that is not a regular file (a FIFO, a
/// device) is written directly (core/output_file.hpp).
///
/// Example:
///
///     emit::Recorder recorder("rec.bin", sensor);
///     while (source.next(frame, timeout)) recorder.record(frame.raw);
///     recorder.close();   // rec.bin.partial → rec.bin
#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "core/frame_packet.hpp"
#include "emit/acquire/raw_frame.hpp"
#include "emit/core/output_file.hpp"
#include "emit/sensor/sensor.hpp"

namespace emit {

class Recorder {
 public:
  /// Writes the header (the sensor's electrode count and ADC: bits, vref) into an output opened
  /// with OutputOptions::partial (core/output_paths.hpp's open_outputs).
  Recorder(OutputFile file, const Sensor& sensor);
  /// Opens PATH (PATH.partial) first. \throw IoError naming the file if it cannot be created.
  Recorder(const std::string& path, const Sensor& sensor);
  /// close(), errors swallowed (a destructor must not throw): call close() to see them.
  ~Recorder();
  Recorder(const Recorder&) = delete;
  Recorder& operator=(const Recorder&) = delete;

  /// A decoded packet, re-encoded byte for byte as the board sent it.
  /// \throw InvalidInput if its N is not the recording's; IoError if the write fails.
  void record(const RawFrame& frame);

  /// Flush, close and rename PATH.partial to PATH. Later calls do nothing. \throw IoError.
  void close();
  /// Flush and close, but leave PATH.partial (every packet recorded, whole) and PATH untouched:
  /// a run that failed. Later calls, and close(), do nothing. \throw IoError.
  void close_partial();

  std::uint64_t frames() const { return frames_; }
  const std::string& path() const { return file_.path(); }

 private:
  void write_packet(const firmware::PacketHeader& header, const std::uint16_t* counts);

  OutputFile file_;
  int electrode_count_;
  std::vector<std::uint8_t> packet_;
  std::uint64_t frames_ = 0;
  bool closed_ = false;
};

}  // namespace emit
