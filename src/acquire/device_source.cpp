#include "emit/acquire/device_source.hpp"

#include <algorithm>
#include <cmath>

#include "emit/acquire/file_source.hpp"
#include "emit/acquire/serial_source.hpp"
#include "emit/core/errors.hpp"

namespace emit {
namespace {

bool starts_with(const std::string& text, const std::string& prefix) { return text.rfind(prefix, 0) == 0; }

/// "serial:PATH" or "serial:PATH@BAUD" → a serial source.
std::unique_ptr<FrameSource> open_serial(const std::string& spec, const Sensor& sensor, double reconnect_s) {
  std::string path = spec.substr(7);
  unsigned baud = default_serial_baud;
  if (const std::size_t at = path.rfind('@'); at != std::string::npos) {
    const std::string digits = path.substr(at + 1);
    if (digits.empty() || digits.size() > 9 || digits.find_first_not_of("0123456789") != std::string::npos ||
        std::stoul(digits) == 0)
      throw InvalidInput("source \"" + spec + "\": the baud rate after '@' must be a positive whole number");
    baud = static_cast<unsigned>(std::stoul(digits));
    path.resize(at);
  }
  if (path.empty()) throw InvalidInput("source \"" + spec + "\": no device path; expected serial:PATH[@BAUD]");
  const auto give_up_after = std::chrono::milliseconds(std::llround(std::min(reconnect_s, 1e9) * 1e3));
  return std::make_unique<SerialSource>(path, baud, sensor, std::chrono::milliseconds(500), give_up_after);
}

}  // namespace

std::unique_ptr<FrameSource> open_device_source(const std::string& spec, const Sensor& sensor,
                                                const SourceOptions& options) {
  if (starts_with(spec, "serial:")) {
    if (options.loop)
      throw InvalidInput("source \"" + spec + "\": only a recording (file:PATH) can be replayed in a loop");
    return open_serial(spec, sensor, options.reconnect_s);
  }
  if (starts_with(spec, "file:")) {
    const std::string path = spec.substr(5);
    if (path.empty()) throw InvalidInput("source \"" + spec + "\": no file path; expected file:PATH");
    return std::make_unique<FileSource>(path, sensor, options.frames_per_s == 0, options.loop);
  }
  return nullptr;
}

}  // namespace emit
