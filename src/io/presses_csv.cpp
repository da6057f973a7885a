#include "emit/io/presses_csv.hpp"

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <sstream>

#include "emit/core/atomic_file.hpp"
#include "emit/core/errors.hpp"

namespace emit {

namespace {
const char* const header = "frame,x_mm,y_mm,radius_mm,force_N,pressure_N_per_mm2";
}

void write_presses_csv(const std::string& path, const PressSequence& sequence) {
  AtomicFile file(path);
  auto& out = file.stream();
  out << header << '\n';
  char row[256];
  for (std::size_t f = 0; f < sequence.size(); ++f)
    for (const Press& p : sequence[f]) {
      std::snprintf(row, sizeof row, "%zu,%.4f,%.4f,%.4f,%.6f,%.6f\n", f, p.x_mm, p.y_mm, p.radius_mm, p.force_N,
                    p.pressure_N_per_mm2());
      out << row;
    }
  file.commit();
}

PressSequence read_presses_csv(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw IoError(path + ": cannot open presses file (" + std::strerror(errno) + ")");
  std::string line;
  if (!std::getline(in, line) || line.rfind("frame,x_mm,y_mm,radius_mm,force_N", 0) != 0)
    throw InvalidInput(path + ":1: expected the header \"" + std::string(header) + "\"");
  PressSequence sequence;
  for (int line_number = 2; std::getline(in, line); ++line_number) {
    if (line.find_first_not_of(" \t\r") == std::string::npos) continue;
    long frame = -1;
    Press p;
    // glibc's sscanf converts as strtol and strtod do (saturating on overflow); the field count
    // rejects a malformed line, the check below a negative frame.
    // NOLINTNEXTLINE(cert-err34-c)
    if (std::sscanf(line.c_str(), "%ld,%lf,%lf,%lf,%lf", &frame, &p.x_mm, &p.y_mm, &p.radius_mm, &p.force_N) != 5 ||
        frame < 0)
      throw InvalidInput(path + ":" + std::to_string(line_number) + ": expected frame,x_mm,y_mm,radius_mm,force_N");
    if (static_cast<std::size_t>(frame) >= sequence.size()) sequence.resize(static_cast<std::size_t>(frame) + 1);
    sequence[static_cast<std::size_t>(frame)].push_back(p);
  }
  return sequence;
}

}  // namespace emit
