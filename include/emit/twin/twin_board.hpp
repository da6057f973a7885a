#pragma once
/// \file twin_board.hpp
/// The acquisition board simulated on the host: a firmware::Board whose multiplexers and ADC read
/// the digital twin, so the firmware core's Scanner (firmware/core/scan.hpp) runs unchanged on the
/// host and its packets go wherever the sink sends them (a pseudo-terminal in the serial
/// end-to-end test, a pipe or socket for a live demo).
///
/// At the start of each scan (the ground multiplexer enabled after being disabled, as the Scanner
/// does between frames) the board draws one twin frame, Twin::frame(presses), with the presses of
/// the last set_presses(); each ADC reading of that scan is the frame's voltage at (grounded,
/// sensed) electrode in counts of the sensor's ADC. Fresh ADC noise every scan, like a real board.
///
/// Example:
///
///     emit::Twin twin(sensor);
///     emit::TwinBoard board(twin, emit::fd_sink(pty_master));
///     emit::firmware::Scanner scanner({});
///     board.set_presses({{20, 20, 5, 10}});
///     scanner.scan_and_send(board);   // one packet v1 to the pty
#include <array>
#include <chrono>
#include <cstdint>
#include <functional>
#include <vector>

#include "core/board.hpp"
#include "core/scan.hpp"
#include "emit/twin/twin.hpp"

namespace emit {

/// Where a TwinBoard's serial writes go: `count` bytes at `bytes`.
using ByteSink = std::function<void(const std::uint8_t* bytes, std::size_t count)>;

/// A sink that writes everything to file descriptor `fd` (not owned), resuming partial and
/// interrupted writes. \throw IoError if a write fails (e.g. the other end of a pty closed).
ByteSink fd_sink(int fd);

class TwinBoard : public firmware::Board {
 public:
  /// Keeps a reference to `twin`, which must outlive the board. `scan` gives the electrode ↔
  /// multiplexer channel wiring the Scanner uses (identity by default).
  TwinBoard(Twin& twin, ByteSink sink, const firmware::ScanOptions& scan = {});

  /// The presses of the scans that start from now on.
  void set_presses(std::vector<Press> presses) { presses_ = std::move(presses); }
  /// Frames drawn from the twin so far (one per scan).
  int scans() const { return scans_; }

  void set_mux(firmware::Mux mux, firmware::MuxControl control) override;
  void wait_us(std::uint32_t) override {}  ///< the twin settles at once
  /// The voltage of the current (ground, sense) pair in ADC counts: round(v / vref · (2^bits − 1)),
  /// clipped to the ADC's range; 0 while either multiplexer is off.
  std::uint16_t read_adc() override;
  /// Microseconds of the host's steady clock, wrapping at 2^32 like the ESP32's micros().
  std::uint32_t micros() override;
  void write(const std::uint8_t* bytes, std::size_t count) override { sink_(bytes, count); }

 private:
  Twin& twin_;
  ByteSink sink_;
  std::array<int, firmware::mux_channel_count> electrode_of_channel_{};  ///< −1: not wired
  std::vector<Press> presses_;
  Frame frame_;
  firmware::MuxControl ground_, sense_;
  int scans_ = 0;
};

}  // namespace emit
