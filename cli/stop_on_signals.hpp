#pragma once
// SIGINT, SIGTERM and SIGHUP set a stop flag while a StopOnSignals lives, so that a long command
// (emit live, emit calibrate --capture) finishes its frame, keeps what it wrote and returns; the
// old handlers come back after.
#include <array>
#include <atomic>
#include <csignal>

namespace emit::cli {

class StopOnSignals {
 public:
  /// Clears the flag and installs the handlers.
  StopOnSignals();
  StopOnSignals(const StopOnSignals&) = delete;  // one owner restores the old handlers, once
  StopOnSignals& operator=(const StopOnSignals&) = delete;
  ~StopOnSignals();
  /// Set by a signal since construction.
  static const std::atomic<bool>& flag();

 private:
  static constexpr std::array<int, 3> signals_{SIGINT, SIGTERM, SIGHUP};
  std::array<struct sigaction, 3> old_{};
};

/// Thrown by a command that ends with an exit code of its own (130 after Ctrl-C, as a shell's);
/// main() returns it, having printed nothing more.
struct ExitCode {
  int code;
};

}  // namespace emit::cli
