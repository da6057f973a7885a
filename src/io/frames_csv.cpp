#include "emit/io/frames_csv.hpp"

#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>

#include "emit/core/atomic_file.hpp"
#include "emit/core/errors.hpp"

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

std::vector<Frame> read_frames_csv(const std::string& path, int electrode_count) {
  std::ifstream in(path);
  if (!in) throw IoError(path + ": cannot open frames file (" + std::strerror(errno) + ")");
  const Index values_per_frame = static_cast<Index>(electrode_count) * electrode_count;
  std::vector<Frame> frames;
  std::string line;
  for (int line_number = 1; std::getline(in, line); ++line_number) {
    if (line.find_first_not_of(" \t\r") == std::string::npos) continue;
    const std::string where = path + ":" + std::to_string(line_number);
    Frame frame(electrode_count, electrode_count);
    Index count = 0;
    const char* p = line.c_str();
    while (true) {
      char* end = nullptr;
      const double value = std::strtod(p, &end);
      const char* stop = end;
      while (*stop == ' ' || *stop == '\t' || *stop == '\r') ++stop;
      if (end == p || (*stop != ',' && *stop != '\0')) {
        std::string text(p, std::strcspn(p, ","));
        throw InvalidInput(where + ": value " + std::to_string(count + 1) + " \"" + text + "\" is not a number");
      }
      if (!std::isfinite(value))
        throw InvalidInput(where + ": value " + std::to_string(count + 1) + " is " +
                           std::string(p, static_cast<std::size_t>(end - p)));
      if (count < values_per_frame) frame.data()[count] = value;
      ++count;
      if (*stop == '\0') break;
      p = stop + 1;
    }
    if (count != values_per_frame)
      throw InvalidInput(where + ": " + std::to_string(count) + " values, expected " +
                         std::to_string(values_per_frame) + " (" + std::to_string(electrode_count) + " electrodes)");
    frames.push_back(std::move(frame));
  }
  return frames;
}

}  // namespace emit
