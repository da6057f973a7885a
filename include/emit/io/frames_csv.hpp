#pragma once
/// \file frames_csv.hpp
/// Frames as CSV (README, "Files"): one frame per line, N·N comma-separated volts, ground-major
/// (index l·N + m), no header. Blank lines are skipped; a UTF-8 byte-order mark and "\r\n" endings
/// are accepted; a line is at most LineReader::default_max_line_bytes long.
#include <ostream>
#include <string>
#include <vector>

#include "emit/core/types.hpp"
#include "emit/io/line_reader.hpp"

namespace emit {

/// Write all frames (each N×N) to `path` as core/output_file.hpp says: a file is replaced only
/// when the whole file is written. \throw IoError.
void write_frames_csv(const std::string& path, const std::vector<Frame>& frames);
/// The same text into a stream (an opened output; a failed write shows in its state).
void write_frames_csv(std::ostream& out, const std::vector<Frame>& frames);

/// Frames one at a time, so a file of any length is read in constant memory.
class FramesCsvReader {
 public:
  /// `readings_may_be_missing`: `nan` and `inf` are read as values (a board's dropped or broken
  /// reading, masked by the reconstructor: frame/masked_readings.hpp); else they are errors.
  /// \throw IoError if the file cannot be opened.
  FramesCsvReader(const std::string& path, int electrode_count, bool readings_may_be_missing = false);
  /// The next frame into `frame` (resized to N×N). \return false at the end of the file.
  /// \throw InvalidInput naming the line and value for a wrong value count, text, or (unless
  /// readings may be missing) NaN or infinity.
  bool next(Frame& frame);
  std::string where() const { return lines_.where(); }  ///< "<path>:<line>" of the last frame
  long frames_read() const { return frames_read_; }

 private:
  LineReader lines_;
  int electrode_count_;
  bool readings_may_be_missing_;
  std::string line_;
  std::vector<double> values_;  ///< the line's numbers, kept between lines
  long frames_read_ = 0;
};

/// Read all frames of `electrode_count` electrodes. \throw IoError if unreadable; InvalidInput
/// as FramesCsvReader::next, or "<path>: no frames" for a file without any.
std::vector<Frame> read_frames_csv(const std::string& path, int electrode_count, bool readings_may_be_missing = false);

}  // namespace emit
