#include "emit/io/frames_csv.hpp"

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string_view>

#include "emit/core/atomic_file.hpp"
#include "emit/core/errors.hpp"
#include "emit/core/quote_input.hpp"

namespace emit {

void write_frames_csv(const std::string& path, const std::vector<Frame>& frames) {
  AtomicFile file(path);
  auto& out = file.stream();
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
  file.commit();
}

FramesCsvReader::FramesCsvReader(const std::string& path, int electrode_count)
    : lines_(path, "frames file"), electrode_count_(electrode_count) {}

bool FramesCsvReader::next(Frame& frame) {
  do {
    if (!lines_.next(line_)) return false;
  } while (line_.find_first_not_of(" \t") == std::string::npos);
  const Index values_per_frame = static_cast<Index>(electrode_count_) * electrode_count_;
  frame.resize(electrode_count_, electrode_count_);
  Index count = 0;
  const char* p = line_.c_str();
  const char* const line_end = p + line_.size();
  while (true) {
    char* end = nullptr;
    const double value = std::strtod(p, &end);
    const char* stop = end;
    while (*stop == ' ' || *stop == '\t') ++stop;
    if (end == p || (*stop != ',' && stop != line_end)) {
      const char* field_end = std::find(p, line_end, ',');
      throw InvalidInput(where() + ": value " + std::to_string(count + 1) + " " +
                         quote_input(std::string_view(p, static_cast<std::size_t>(field_end - p))) +
                         " is not a number");
    }
    if (!std::isfinite(value))
      throw InvalidInput(where() + ": value " + std::to_string(count + 1) + " is " +
                         std::string(p, static_cast<std::size_t>(end - p)));
    if (count < values_per_frame) frame.data()[count] = value;
    ++count;
    if (stop == line_end) break;
    p = stop + 1;
  }
  if (count != values_per_frame)
    throw InvalidInput(where() + ": " + std::to_string(count) + " values, expected " +
                       std::to_string(values_per_frame) + " (" + std::to_string(electrode_count_) + " electrodes)");
  ++frames_read_;
  return true;
}

std::vector<Frame> read_frames_csv(const std::string& path, int electrode_count) {
  FramesCsvReader reader(path, electrode_count);
  std::vector<Frame> frames;
  for (Frame frame; reader.next(frame);) frames.push_back(frame);
  if (frames.empty()) throw InvalidInput(path + ": no frames (an empty file?)");
  return frames;
}

}  // namespace emit
