#pragma once
// A pseudo-terminal for the serial tests: the master end plays the board's USB-UART, the slave's
// path (/dev/pts/N) is what the host opens as a serial port. Raw mode, so every byte crosses
// unchanged (no echo, no CR/LF mapping, no XON/XOFF).
#include <fcntl.h>
#include <stdlib.h>  // NOLINT(modernize-deprecated-headers): POSIX's posix_openpt, grantpt, ptsname
#include <termios.h>
#include <unistd.h>

#include <array>
#include <stdexcept>
#include <string>

namespace emit::test {

class PseudoTerminal {
 public:
  PseudoTerminal() {
    master_ = ::posix_openpt(O_RDWR | O_NOCTTY);
    if (master_ < 0 || ::grantpt(master_) != 0 || ::unlockpt(master_) != 0) throw std::runtime_error("no pty");
    std::array<char, 128> name{};
    if (::ptsname_r(master_, name.data(), name.size()) != 0) throw std::runtime_error("no ptsname");
    slave_path_ = name.data();
    termios mode{};
    ::tcgetattr(master_, &mode);
    ::cfmakeraw(&mode);  // on a master this sets the pair's line discipline, the slave's side
    ::tcsetattr(master_, TCSANOW, &mode);
  }
  ~PseudoTerminal() { close_master(); }
  PseudoTerminal(const PseudoTerminal&) = delete;
  PseudoTerminal& operator=(const PseudoTerminal&) = delete;

  int master() const { return master_; }
  const std::string& slave_path() const { return slave_path_; }
  /// The cable pulled: the slave's reads fail with EIO from now on.
  void close_master() {
    if (master_ >= 0) ::close(master_);
    master_ = -1;
  }

 private:
  int master_ = -1;
  std::string slave_path_;
};

}  // namespace emit::test
