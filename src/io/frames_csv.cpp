#include "emit/io/frames_csv.hpp"

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string_view>

#include "emit/core/errors.hpp"
#include "emit/core/output_file.hpp"
#include "emit/io/csv_numbers.hpp"

namespace emit {

void write_frames_csv(const std::string& path, const std::vector<Frame>& frames) {
  OutputFile file({"", path});
  write_frames_csv(file.stream(), frames);
  file.commit();
}

void write_frames_csv(std::ostream& out, const std::vector<Frame>& frames) {
  char number[32];
  for (const Frame& frame : frames) {
    for (Index i = 0; i < frame.size(); ++i) {
      // Round-off below the printed resolution would print as "-0.0000000".
      const double value = std::abs(frame.data()[i]) < 5e-8 ? 0.0 : frame.data()[i];
      std::snprintf(number, sizeof number, "%.7f", value);
      if (i > 0) out << ',';
      out << number;
    }
    out << '\n';
  }
}

FramesCsvReader::FramesCsvReader(const std::string& path, int electrode_count, bool readings_may_be_missing)
    : lines_(path, "frames file"),
      electrode_count_(electrode_count),
      readings_may_be_missing_(readings_may_be_missing) {}

bool FramesCsvReader::next(Frame& frame) {
  do {
    if (!lines_.next(line_)) return false;
  } while (line_.find_first_not_of(" \t") == std::string::npos);
  const Index values_per_frame = static_cast<Index>(electrode_count_) * electrode_count_;
  parse_csv_numbers(line_, lines_, values_, readings_may_be_missing_);
  const auto count = static_cast<Index>(values_.size());
  if (count != values_per_frame)
    throw InvalidInput(where() + ": " + std::to_string(count) + " values, expected " +
                       std::to_string(values_per_frame) + " (" + std::to_string(electrode_count_) + " electrodes)");
  frame.resize(electrode_count_, electrode_count_);
  std::copy(values_.begin(), values_.end(), frame.data());
  ++frames_read_;
  return true;
}

std::vector<Frame> read_frames_csv(const std::string& path, int electrode_count, bool readings_may_be_missing) {
  FramesCsvReader reader(path, electrode_count, readings_may_be_missing);
  std::vector<Frame> frames;
  for (Frame frame; reader.next(frame);) frames.push_back(frame);
  if (frames.empty()) throw InvalidInput(path + ": no frames (an empty file?)");
  return frames;
}

}  // namespace emit
