// emit_board: the acquisition board's firmware for an ESP32 (ESP-WROOM-32, Arduino core ≥ 3.0).
// Implements the core's Board interface (src/core/board.hpp) with GPIOs for two ADG726
// multiplexers, analogRead on ADC1 and Serial at 921600 baud, then loops: scan, encode, write.
// Wiring and packet format: firmware/README.md. Not built by the host build (no ESP32 toolchain).
#include <Arduino.h>

#include "src/core/scan.hpp"

namespace {

using emit::firmware::Mux;
using emit::firmware::MuxControl;

// GPIOs (firmware/README.md, "Wiring"). Strapping (0, 2, 5, 12, 15), flash (6–11) and
// input-only (34–39) pins are avoided for outputs.
constexpr int pin_address[4] = {16, 17, 18, 19};  // A0..A3, shared by both ADG726
constexpr int pin_wr[2] = {21, 22};                // /WR of the ground mux, of the sense mux
constexpr int pin_en[2] = {23, 25};                // /EN of the ground mux, of the sense mux
constexpr int pin_adc = 36;                        // VP = ADC1_CH0, the sense mux's drain
constexpr unsigned long baud = 921600;

class Esp32Board final : public emit::firmware::Board {
 public:
  void begin() {
    for (int pin : pin_address) pinMode(pin, OUTPUT);
    for (int i = 0; i < 2; ++i) {
      pinMode(pin_en[i], OUTPUT);
      digitalWrite(pin_en[i], HIGH);  // disabled: no electrode connected
      pinMode(pin_wr[i], OUTPUT);
      digitalWrite(pin_wr[i], HIGH);
    }
    analogReadResolution(12);
    analogSetPinAttenuation(pin_adc, ADC_11db);  // about 0..3.1 V full scale
  }

  // The address lines are shared: put the address on A0..A3, then /WR low (the selected
  // multiplexer's latch is transparent) and high (the rising edge latches it). /EN is per chip.
  void set_mux(Mux mux, MuxControl control) override {
    const int chip = static_cast<int>(mux);
    if (!control.enabled) digitalWrite(pin_en[chip], HIGH);  // off before the address changes
    for (int k = 0; k < 4; ++k) digitalWrite(pin_address[k], (control.address >> k) & 1u);
    digitalWrite(pin_wr[chip], LOW);
    digitalWrite(pin_wr[chip], HIGH);
    if (control.enabled) digitalWrite(pin_en[chip], LOW);
  }
  void wait_us(std::uint32_t microseconds) override { delayMicroseconds(microseconds); }
  std::uint16_t read_adc() override { return static_cast<std::uint16_t>(analogRead(pin_adc)); }
  std::uint32_t micros() override { return static_cast<std::uint32_t>(::micros()); }
  void write(const std::uint8_t* bytes, std::size_t count) override { Serial.write(bytes, count); }
};

emit::firmware::ScanOptions scan_options() {
  emit::firmware::ScanOptions options;  // 16 electrodes on S1..S16, 12 bits
  options.oversampling = 4;
  options.settle_after_ground_us = 100;
  options.settle_after_sense_us = 20;
  return options;
}

Esp32Board board;
emit::firmware::Scanner scanner(scan_options());

}  // namespace

void setup() {
  Serial.setTxBufferSize(1024);  // a whole 532-byte packet: it drains while the next scan runs
  Serial.begin(baud);
  board.begin();
}

void loop() {
  if (scanner.error() != nullptr) {  // options are constants: this is a build mistake
    Serial.println(scanner.error());
    delay(1000);
    return;
  }
  scanner.scan_and_send(board);
}
