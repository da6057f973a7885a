#pragma once
/// \file board.hpp
/// The hardware the firmware core drives, as a small interface: two ADG726 multiplexers (one
/// grounds an electrode, one connects an electrode to the ADC), a microsecond clock and delay, one
/// ADC conversion, and the serial link. The ESP32 sketch implements it with GPIOs, analogRead and
/// Serial (firmware/esp32/); the host tests implement it with a recording fake.
///
/// Portable C++17: no exceptions, no heap, no iostream, so it builds for the ESP32 as well.
#include <cstddef>
#include <cstdint>

namespace emit::firmware {

/// Which of the two multiplexers.
enum class Mux : std::uint8_t {
  ground = 0,  ///< its common drain D is tied to ground: the selected electrode is grounded
  sense = 1,   ///< its common drain D goes to the ADC input: the selected electrode is read
};

/// One ADG726 multiplexer has 16 channels S1..S16, addressed by A3..A0 = channel − 1.
constexpr int mux_channel_count = 16;

/// The control word written to one ADG726: address lines A3..A0 (bit k drives Ak; value 0..15
/// connects S(address+1) to D) and the enable. `enabled == false` means /EN high, all switches off.
struct MuxControl {
  std::uint8_t address = 0;  ///< 0..15, bit k → pin Ak
  bool enabled = false;      ///< true → /EN driven low
  friend bool operator==(const MuxControl& a, const MuxControl& b) {
    return a.address == b.address && a.enabled == b.enabled;
  }
};

/// The board as the scan sequencer sees it. Calls happen from one thread (the MCU's loop).
class Board {
 public:
  virtual ~Board() = default;
  /// Drive A0–A3 and /EN of `mux` to `control` and latch them (a /WR pulse on the ADG726). On
  /// return the switch is set; analog settling is the caller's business (wait_us).
  virtual void set_mux(Mux mux, MuxControl control) = 0;
  /// Busy-wait `microseconds` µs.
  virtual void wait_us(std::uint32_t microseconds) = 0;
  /// One ADC conversion of the sense line, raw counts in 0..2^bits − 1.
  virtual std::uint16_t read_adc() = 0;
  /// Free-running microsecond clock (wraps at 2^32 µs ≈ 71.6 minutes).
  virtual std::uint32_t micros() = 0;
  /// Write `count` bytes to the serial link (blocking until queued).
  virtual void write(const std::uint8_t* bytes, std::size_t count) = 0;
};

}  // namespace emit::firmware
