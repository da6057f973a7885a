#include "stop_on_signals.hpp"

namespace emit::cli {

namespace {
std::atomic<bool> stop_requested{false};
extern "C" void request_stop(int) { stop_requested = true; }
}  // namespace

StopOnSignals::StopOnSignals() {
  stop_requested = false;
  struct sigaction action {};
  action.sa_handler = request_stop;
  sigemptyset(&action.sa_mask);
  for (std::size_t k = 0; k < signals_.size(); ++k) sigaction(signals_[k], &action, &old_[k]);
}

StopOnSignals::~StopOnSignals() {
  for (std::size_t k = 0; k < signals_.size(); ++k) sigaction(signals_[k], &old_[k], nullptr);
}

const std::atomic<bool>& StopOnSignals::flag() { return stop_requested; }

}  // namespace emit::cli
