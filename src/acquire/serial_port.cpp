#include "emit/acquire/serial_port.hpp"

#include <poll.h>

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <utility>  // before Asio: Boost 1.74's awaitable.hpp uses std::exchange under C++20

#include <boost/asio/io_context.hpp>
#include <boost/asio/serial_port.hpp>

#include "emit/core/errors.hpp"

namespace emit {
namespace asio = boost::asio;

struct SerialPort::Impl {
  asio::io_context io;
  asio::serial_port port{io};
};

SerialPort::SerialPort() : impl_(std::make_unique<Impl>()) {}
SerialPort::~SerialPort() { close(); }

bool SerialPort::is_open() const { return impl_->port.is_open(); }

void SerialPort::close() {
  boost::system::error_code ignored;
  impl_->port.close(ignored);
}

bool SerialPort::try_open(const std::string& path, unsigned baud) {
  close();
  boost::system::error_code ec;
  // Asio opens with O_NOCTTY and sets the line raw (no echo, no canonical mode, no CR/LF mapping).
  impl_->port.open(path, ec);
  using base = asio::serial_port_base;
  if (!ec) impl_->port.set_option(base::baud_rate(baud), ec);
  if (!ec) impl_->port.set_option(base::character_size(8), ec);
  if (!ec) impl_->port.set_option(base::parity(base::parity::none), ec);
  if (!ec) impl_->port.set_option(base::stop_bits(base::stop_bits::one), ec);
  if (!ec) impl_->port.set_option(base::flow_control(base::flow_control::none), ec);
  if (ec) {
    error_ = path + ": cannot open serial port at " + std::to_string(baud) + " baud: " + ec.message();
    close();
    return false;
  }
  error_.clear();
  return true;
}

void SerialPort::open(const std::string& path, unsigned baud) {
  if (!try_open(path, baud)) throw IoError(error_);
}

SerialRead SerialPort::read_some(std::span<std::uint8_t> buffer, std::chrono::milliseconds timeout) {
  pollfd descriptor{impl_->port.native_handle(), POLLIN, 0};
  const auto deadline = std::chrono::steady_clock::now() + timeout;
  for (;;) {
    // Rounded up: poll(2) takes whole ms, and must not return before the deadline.
    const auto left = std::chrono::ceil<std::chrono::milliseconds>(deadline - std::chrono::steady_clock::now());
    const int ready = ::poll(&descriptor, 1, static_cast<int>(std::max<std::int64_t>(0, left.count())));
    if (ready > 0) break;
    if (ready == 0) return {};  // timeout
    if (errno != EINTR) {
      error_ = std::string("serial port: poll failed: ") + std::strerror(errno);
      return {0, true};
    }
  }
  // Readable, or hung up / in error: the read says which (0 bytes is end of file, EIO a pty whose
  // master closed or a USB-UART unplugged).
  boost::system::error_code ec;
  const std::size_t count = impl_->port.read_some(asio::buffer(buffer.data(), buffer.size()), ec);
  if (ec) {
    error_ = "serial port disconnected: " + ec.message();
    return {0, true};
  }
  return {count, false};
}

}  // namespace emit
