#include "emit/twin/twin_board.hpp"

#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstring>
#include <string>

#include "emit/core/errors.hpp"
#include "emit/sensor/adc.hpp"

namespace emit {

ByteSink fd_sink(int fd) {
  return [fd](const std::uint8_t* bytes, std::size_t count) {
    while (count > 0) {
      const ssize_t written = ::write(fd, bytes, count);
      if (written < 0 && errno == EINTR) continue;
      if (written < 0) throw IoError(std::string("twin board: write failed: ") + std::strerror(errno));
      bytes += written;
      count -= static_cast<std::size_t>(written);
    }
  };
}

TwinBoard::TwinBoard(Twin& twin, ByteSink sink, const firmware::ScanOptions& scan)
    : twin_(twin), sink_(std::move(sink)) {
  electrode_of_channel_.fill(-1);
  for (int e = 0; e < scan.electrode_count; ++e)
    electrode_of_channel_[scan.channel_of_electrode[static_cast<std::size_t>(e)] % firmware::mux_channel_count] = e;
}

void TwinBoard::set_mux(firmware::Mux mux, firmware::MuxControl control) {
  if (mux == firmware::Mux::ground && control.enabled && !ground_.enabled) {  // a scan starts
    frame_ = twin_.frame(presses_);
    ++scans_;
  }
  (mux == firmware::Mux::ground ? ground_ : sense_) = control;
}

std::uint16_t TwinBoard::read_adc() {
  if (!ground_.enabled || !sense_.enabled || frame_.size() == 0) return 0;
  const int g = electrode_of_channel_[ground_.address % firmware::mux_channel_count];
  const int s = electrode_of_channel_[sense_.address % firmware::mux_channel_count];
  if (g < 0 || s < 0 || g >= frame_.rows() || s >= frame_.cols()) return 0;
  return adc_code(twin_.sensor().adc, frame_(g, s));
}

std::uint32_t TwinBoard::micros() {
  const auto since_epoch = std::chrono::steady_clock::now().time_since_epoch();
  return static_cast<std::uint32_t>(std::chrono::duration_cast<std::chrono::microseconds>(since_epoch).count());
}

}  // namespace emit
