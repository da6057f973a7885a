#pragma once
/// \file serial_port.hpp
/// A serial port opened raw (8 data bits, no parity, 1 stop bit, no flow control, no line
/// discipline) for the board's packet stream, read with a timeout. Boost.Asio opens and configures
/// it (it opens pseudo-terminals as well as USB-UARTs, which the end-to-end test needs); reads
/// wait with poll(2) on its descriptor, so a read allocates nothing.
///
/// A disconnect (end of file, EIO, the device unplugged) is reported as such, not thrown: the
/// caller closes the port and reopens it when the device is back (serial_source.hpp).
///
/// Example:
///
///     emit::SerialPort port;
///     port.open("/dev/ttyUSB0", 921600);               // throws IoError naming the path
///     std::array<std::uint8_t, 4096> buffer;
///     const emit::SerialRead r = port.read_some(buffer, std::chrono::milliseconds(100));
///     if (r.disconnected) port.close();                 // port.error() says why
#include <chrono>
#include <cstddef>
#include <cstdint>
#include <memory>
#include <span>
#include <string>

namespace emit {

/// What one read_some() got.
struct SerialRead {
  std::size_t bytes = 0;      ///< bytes stored at the buffer's start; 0 on timeout or disconnect
  bool disconnected = false;  ///< the device went away; the port must be closed (and reopened)
};

class SerialPort {
 public:
  SerialPort();
  ~SerialPort();
  SerialPort(const SerialPort&) = delete;
  SerialPort& operator=(const SerialPort&) = delete;

  /// Open `path` at `baud` bits/s, 8N1, raw, no flow control. Closes a port already open first.
  /// \throw IoError naming the path and the reason (no such device, permission, not a tty).
  void open(const std::string& path, unsigned baud);
  /// Open without throwing (for reconnect attempts). \return false and error() says why.
  bool try_open(const std::string& path, unsigned baud);
  void close();
  bool is_open() const;

  /// Wait up to `timeout` for bytes and read as many as are ready (at most buffer.size()).
  /// \pre is_open(). Interrupted waits are resumed; a disconnect sets error().
  SerialRead read_some(std::span<std::uint8_t> buffer, std::chrono::milliseconds timeout);

  /// Why the last open failed or the device disconnected, one line; empty if neither happened.
  const std::string& error() const { return error_; }

 private:
  struct Impl;  // the Asio objects, kept out of this header
  std::unique_ptr<Impl> impl_;
  std::string error_;
};

}  // namespace emit
