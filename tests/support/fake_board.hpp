#pragma once
// A fake acquisition board for the firmware core's host tests: it records every call the scan
// makes, in order, and answers ADC reads from a function of the two multiplexers' addresses.
#include <cstdint>
#include <functional>
#include <vector>

#include "core/board.hpp"

namespace emit::test {

class FakeBoard : public firmware::Board {
 public:
  enum class Kind { set_mux, wait, read_adc, micros, write };
  struct Event {
    Kind kind;
    firmware::Mux mux = firmware::Mux::ground;  // set_mux
    firmware::MuxControl control;               // set_mux: what was written
    firmware::MuxControl ground, sense;         // read_adc: the multiplexers' state when read
    std::uint32_t value = 0;                    // wait: µs; read_adc: the reading; micros: time
  };

  /// ADC reading for (ground address, sense address, k-th read at this setting).
  std::function<std::uint16_t(int, int, int)> adc = [](int g, int s, int) {
    return static_cast<std::uint16_t>(100 * g + s);
  };
  std::uint32_t clock_us = 1000;  // advanced by wait_us
  std::vector<Event> events;
  std::vector<std::uint8_t> written;

  void set_mux(firmware::Mux mux, firmware::MuxControl control) override {
    (mux == firmware::Mux::ground ? ground_ : sense_) = control;
    reads_here_ = 0;
    events.push_back({Kind::set_mux, mux, control, {}, {}, 0});
  }
  void wait_us(std::uint32_t microseconds) override {
    clock_us += microseconds;
    events.push_back({Kind::wait, {}, {}, {}, {}, microseconds});
  }
  std::uint16_t read_adc() override {
    const std::uint16_t value = adc(ground_.address, sense_.address, reads_here_++);
    events.push_back({Kind::read_adc, {}, {}, ground_, sense_, value});
    return value;
  }
  std::uint32_t micros() override {
    events.push_back({Kind::micros, {}, {}, {}, {}, clock_us});
    return clock_us;
  }
  void write(const std::uint8_t* bytes, std::size_t count) override {
    written.insert(written.end(), bytes, bytes + count);
    events.push_back({Kind::write, {}, {}, {}, {}, static_cast<std::uint32_t>(count)});
  }

  std::vector<Event> of_kind(Kind kind) const {
    std::vector<Event> selected;
    for (const Event& e : events)
      if (e.kind == kind) selected.push_back(e);
    return selected;
  }

 private:
  firmware::MuxControl ground_, sense_;
  int reads_here_ = 0;
};

}  // namespace emit::test
