#pragma once
/// \file serial_source.hpp
/// Frames from the acquisition board over a serial port ("serial:/dev/ttyUSB0[@BAUD]"): bytes →
/// PacketDecoder (packet v1) → volts with the sensor's ADC reference.
///
/// A pulled cable does not end the source: the port is closed, the decoder's stream restarted (a
/// half packet is dropped, the gap in sequence numbers is not counted), and the path reopened
/// every retry interval; meanwhile next() returns false and status() says "disconnected,
/// retrying". When the device is back, frames resume. A device that is not back within the
/// reconnection time (SourceOptions::reconnect_s, 30 s by default; `emit live --reconnect-s`) is
/// gone for good: next() throws IoError "serial:PATH at BAUD baud: disconnected for 30 s and not
/// back (the last try: No such file or directory)", and again on every later call.
///
/// Once the caller's frame has its N×N size (its first next()) the path allocates nothing: the
/// read buffer, the decoder and a queue of frames are sized at construction, and next() swaps the
/// frame's volts with a queue slot's.
///
/// Example:
///
///     emit::SerialSource source("/dev/ttyUSB0", 921600, sensor);   // IoError if it cannot open
///     emit::SourceFrame frame;
///     for (;;)
///       if (source.next(frame, std::chrono::milliseconds(50))) use(frame.volts);
///       else std::puts(source.status().c_str());
#include <array>
#include <chrono>
#include <cstdint>
#include <string>
#include <vector>

#include "emit/acquire/board_clock.hpp"
#include "emit/acquire/frame_source.hpp"
#include "emit/acquire/packet_decoder.hpp"
#include "emit/acquire/serial_port.hpp"

namespace emit {

/// The default baud rate of the board's USB-UART link (firmware/README.md).
constexpr unsigned default_serial_baud = 921600;

/// What a serial source has seen beyond the decoder's own stats.
struct SerialStats {
  DecoderStats decoder;           ///< frames, corrupt, dropped, garbage bytes (packet_decoder.hpp)
  std::uint64_t overruns = 0;     ///< frames dropped because next() was not called for too long
  std::uint64_t disconnects = 0;  ///< times the device went away
  std::uint64_t reconnects = 0;   ///< times it was reopened afterwards
};

class SerialSource : public FrameSource {
 public:
  /// Open `path` at `baud`. Frames must have the sensor's electrode count; their counts become
  /// volts as counts / (2^bits − 1) · sensor.adc.vref_V.
  /// \throw IoError (one line, naming the path) if the port cannot be opened now.
  /// `give_up_after`: how long a port that went away is retried before the source fails.
  SerialSource(std::string path, unsigned baud, const Sensor& sensor,
               std::chrono::milliseconds retry_interval = std::chrono::milliseconds(500),
               std::chrono::milliseconds give_up_after = std::chrono::seconds(30));

  /// board_time_s: the packet's timestamp unwrapped (board_clock.hpp); received: when the read
  /// that completed the packet returned; sequence: the packet's (32-bit) sequence number.
  /// \throw IoError, for good, if the board's frames do not have the sensor's electrode count or
  ///   the port has been gone longer than `give_up_after`.
  bool next(SourceFrame& frame, std::chrono::milliseconds timeout) override;
  /// Never: a board streams until it fails (next() throws) or the reader stops.
  bool finished() const override { return false; }
  std::string description() const override;

  bool connected() const { return port_.is_open(); }
  /// "connected", or "disconnected, retrying every 0.5 s (<why>)".
  std::string status() const;
  SerialStats stats() const;

 private:
  /// One read (waiting at most `timeout`) into the decoder, frames into the queue.
  void read_once(std::chrono::milliseconds timeout);
  void on_disconnect();
  /// Reopen if the retry time has come. \return whether the port is open now.
  bool try_reconnect(std::chrono::steady_clock::time_point now);
  /// \throw IoError when the port has been gone for give_up_after_ (it is then failed for good).
  void give_up_if_gone(std::chrono::steady_clock::time_point now);
  [[noreturn]] void fail(std::string why);
  void push(const RawFrame& raw, std::chrono::steady_clock::time_point received);
  bool pop(SourceFrame& frame);

  std::string path_;
  unsigned baud_;
  int electrode_count_;
  double vref_V_;
  std::chrono::milliseconds retry_interval_, give_up_after_;
  SerialPort port_;
  PacketDecoder decoder_;
  BoardClock clock_;
  std::array<std::uint8_t, 4096> buffer_{};
  std::vector<SourceFrame> queue_;  ///< ring of decoded frames not yet handed out
  std::size_t queue_head_ = 0, queue_size_ = 0;
  std::chrono::steady_clock::time_point next_retry_, disconnected_at_;
  std::string disconnect_reason_;
  std::string failure_;  ///< why the source failed for good (a wrong electrode count, a port gone)
  SerialStats stats_;
  bool failed_ = false;
};

}  // namespace emit
