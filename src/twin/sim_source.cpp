#include "emit/twin/sim_source.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <utility>
#include <vector>

#include "emit/core/errors.hpp"

namespace emit {

namespace {

constexpr double pace_budget = 0.8;  // of the frame interval the twin may take: the rest is headroom

}  // namespace

SimSource::SimSource(const Sensor& sensor, SimScript script, const SourceOptions& options)
    : sensor_(sensor),
      options_(options),
      twin_(sensor,
            [&] {
              TwinOptions twin;
              twin.noise_seed = options.seed;
              twin.condensed_frames = true;  // the direct solve's frames, several times faster
              return twin;
            }()),
      script_(sensor_, twin_.mesh(), std::move(script), options),
      frames_per_s_(options.frames_per_s) {
  measure_pace();
}

void SimSource::measure_pace() {
  // A few pressed frames of the script, spread over it (exact frames: the ADC's noise stream is
  // left as it was); the first is a warm-up.
  std::vector<std::vector<Press>> pressed;
  for (std::uint64_t k = 0; k < 400 && pressed.size() < 4; k += 37)
    if (auto presses = presses_of(static_cast<std::uint64_t>(options_.untouched_frames) + k); !presses.empty())
      pressed.push_back(std::move(presses));
  if (pressed.empty()) return;
  twin_.exact_frame(pressed.front());
  const auto start = std::chrono::steady_clock::now();
  for (const auto& presses : pressed) twin_.exact_frame(presses);
  measured_frame_s_ = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count() /
                      static_cast<double>(pressed.size());
  if (options_.frames_per_s > 0 && measured_frame_s_ > pace_budget / options_.frames_per_s) {
    frames_per_s_ = std::max(1.0, std::floor(pace_budget / measured_frame_s_));
    script_.set_frames_per_s(frames_per_s_);  // the finger as fast in seconds
  }
}

std::vector<Press> SimSource::presses_of(std::uint64_t sequence) const { return script_.presses_of(sequence); }

SimSource::~SimSource() {
  {
    std::lock_guard lock(mutex_);
    stop_ = true;
  }
  ready_.notify_all();
  if (thread_.joinable()) thread_.join();
}

void SimSource::produce() {
  const auto start = std::chrono::steady_clock::now();
  bool pressed_yet = false;
  try {
    for (std::uint64_t sequence = 0;; ++sequence) {
      SourceFrame frame;
      const auto making = std::chrono::steady_clock::now();
      const std::vector<Press> presses = presses_of(sequence);
      pressed_yet = pressed_yet || !presses.empty();
      frame.volts = twin_.frame(presses, &frame.raw.counts);
      const double made_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - making).count();
      frame.sequence = sequence;
      const double due_s = frames_per_s_ > 0 ? static_cast<double>(sequence) / frames_per_s_ : 0;
      const auto due =
          start + std::chrono::duration_cast<std::chrono::steady_clock::duration>(std::chrono::duration<double>(due_s));
      std::unique_lock lock(mutex_);
      making_s_ += made_s;
      ++made_;
      if (ready_.wait_until(lock, due, [this] { return stop_; })) return;
      frame.received = std::chrono::steady_clock::now();
      frame.board_time_s = frames_per_s_ > 0 ? due_s : std::chrono::duration<double>(frame.received - start).count();
      frame.raw.sequence = static_cast<std::uint32_t>(sequence);  // the packet's fields wrap, as the board's do
      frame.raw.timestamp_us =
          static_cast<std::uint32_t>(static_cast<std::uint64_t>(std::llround(frame.board_time_s * 1e6)));
      frame.raw.electrode_count = static_cast<int>(frame.volts.rows());
      frame.raw.adc_bits = sensor_.adc.bits;
      frame.raw.oversampling = 1;
      // Unpaced, the twin waits for the reader, so every frame is read; paced, so do the frames
      // before its first press: the reference is captured from them, and a person presses once
      // the program is ready, so a reader stalled by a loaded machine must not capture a press.
      if (frames_per_s_ == 0 || !pressed_yet) {
        ready_.wait(lock, [this] { return stop_ || queue_.size() < queue_limit; });
        if (stop_) return;
      } else if (queue_.size() >= queue_limit) {  // paced like a board: its frames come whether read or not
        queue_.pop_front();
        ++dropped_;
      }
      queue_.push_back(std::move(frame));
      lock.unlock();
      ready_.notify_all();
    }
  } catch (const std::exception& e) {
    std::lock_guard lock(mutex_);
    failure_ = std::make_exception_ptr(IoError(std::string("source sim: ") + e.what()));
  }
  ready_.notify_all();
}

bool SimSource::next(SourceFrame& frame, std::chrono::milliseconds timeout) {
  // The twin starts on the first call, not at construction: frames made while the reader is
  // still building its models would only pile up (and the baseline must see the untouched ones).
  if (!thread_.joinable()) thread_ = std::thread([this] { produce(); });
  std::unique_lock lock(mutex_);
  ready_.wait_for(lock, timeout, [this] { return !queue_.empty() || failure_; });
  if (!queue_.empty()) {
    frame = std::move(queue_.front());
    queue_.pop_front();
    lock.unlock();
    ready_.notify_all();  // an unpaced twin may be waiting for room
    return true;
  }
  if (failure_) std::rethrow_exception(failure_);
  return false;
}

bool SimSource::finished() const { return false; }  // the twin streams until it fails (next() throws) or is stopped

double SimSource::frame_cost_s() const {
  std::lock_guard lock(mutex_);
  return made_ > 0 ? making_s_ / static_cast<double>(made_) : 0;
}

std::uint64_t SimSource::dropped() const {
  std::lock_guard lock(mutex_);
  return dropped_;
}

std::string SimSource::description() const {
  char rate[160];
  if (frames_per_s_ > 0 && frames_per_s_ < options_.frames_per_s)
    std::snprintf(rate, sizeof rate,
                  "%g frames/s asked, but a twin frame takes %.1f ms on this machine: running at %g frames/s",
                  options_.frames_per_s, 1e3 * measured_frame_s_, frames_per_s_);
  else if (frames_per_s_ > 0)
    std::snprintf(rate, sizeof rate, "%g frames/s (a twin frame takes %.1f ms)", frames_per_s_,
                  1e3 * measured_frame_s_);
  else std::snprintf(rate, sizeof rate, "as fast as the twin goes");
  return "sim: " + script_.description() + " on " + sensor_.name + ", " + rate + ", ADC noise on";
}

}  // namespace emit
