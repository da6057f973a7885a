#include "emit/core/limits.hpp"

#include <cstdio>

#include "emit/core/errors.hpp"

namespace emit::limits {

std::string thread_count_rule() {
  return "a whole number from 1 to " + std::to_string(max_threads) + " (threads beyond the cores only cost memory)";
}

void check_thread_count(const std::string& name, long long count) {
  if (count < 1 || count > max_threads)
    throw InvalidInput(name + " must be " + thread_count_rule() + ", got " + std::to_string(count));
}

long long max_frames_held(int electrodes) {
  const auto readings = static_cast<long long>(electrodes > 0 ? electrodes : 1);
  return static_cast<long long>(max_frames_bytes) / (readings * readings * static_cast<long long>(sizeof(double)));
}

void check_frames_held(const std::string& what, double frames, int electrodes, const std::string& advice) {
  const long long most = max_frames_held(electrodes);
  if (frames <= static_cast<double>(most)) return;
  char text[200];
  std::snprintf(text, sizeof text,
                ": %.15g frames of %d electrodes, beyond the %lld a run holds in memory (%zu MiB of readings)", frames,
                electrodes, most, max_frames_bytes >> 20);
  throw InvalidInput(what + text + (advice.empty() ? "" : "; " + advice));
}

}  // namespace emit::limits
