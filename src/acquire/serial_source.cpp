#include "emit/acquire/serial_source.hpp"

#include <algorithm>
#include <cstdio>
#include <thread>
#include <utility>

#include "emit/core/errors.hpp"

namespace emit {
namespace {

using Clock = std::chrono::steady_clock;

/// Frames decoded but not yet handed out. One read of the 4 KiB buffer holds at most 7 packets of
/// 16 electrodes; the rest is slack for a slow consumer.
constexpr std::size_t queue_capacity = 64;

std::chrono::milliseconds left_until(Clock::time_point deadline) {
  return std::max(std::chrono::milliseconds(0),
                  std::chrono::duration_cast<std::chrono::milliseconds>(deadline - Clock::now()));
}

}  // namespace

SerialSource::SerialSource(std::string path, unsigned baud, const Sensor& sensor,
                           std::chrono::milliseconds retry_interval, std::chrono::milliseconds give_up_after)
    : path_(std::move(path)),
      baud_(baud),
      electrode_count_(sensor.electrode_count()),
      vref_V_(sensor.adc.vref_V),
      retry_interval_(retry_interval),
      give_up_after_(give_up_after),
      queue_(queue_capacity) {
  for (SourceFrame& slot : queue_) {
    slot.volts.resize(electrode_count_, electrode_count_);
    slot.raw.counts.resize(static_cast<std::size_t>(electrode_count_) * static_cast<std::size_t>(electrode_count_));
  }
  port_.open(path_, baud_);
}

std::string SerialSource::description() const { return "serial:" + path_ + " at " + std::to_string(baud_) + " baud"; }

std::string SerialSource::status() const {
  if (connected()) return "connected";
  char interval[32];
  std::snprintf(interval, sizeof interval, "%g s", 1e-3 * static_cast<double>(retry_interval_.count()));
  return "disconnected, retrying every " + std::string(interval) + " (" + disconnect_reason_ + ")";
}

SerialStats SerialSource::stats() const {
  SerialStats stats = stats_;
  stats.decoder = decoder_.stats();
  return stats;
}

bool SerialSource::next(SourceFrame& frame, std::chrono::milliseconds timeout) {
  if (failed_) throw IoError(failure_);
  const Clock::time_point deadline = Clock::now() + timeout;
  for (;;) {
    if (pop(frame)) return true;
    if (port_.is_open() || try_reconnect(Clock::now())) {
      read_once(left_until(deadline));
      if (queue_size_ > 0) continue;
      if (Clock::now() >= deadline) return false;
    } else {
      give_up_if_gone(Clock::now());
      if (Clock::now() >= deadline) return false;
      std::this_thread::sleep_until(std::min(deadline, next_retry_));
    }
  }
}

void SerialSource::read_once(std::chrono::milliseconds timeout) {
  const SerialRead read = port_.read_some(buffer_, timeout);
  if (read.disconnected) return on_disconnect();
  const Clock::time_point received = Clock::now();
  decoder_.feed(std::span<const std::uint8_t>(buffer_.data(), read.bytes),
                [&](const RawFrame& raw) { push(raw, received); });
}

void SerialSource::on_disconnect() {
  disconnect_reason_ = port_.error();
  port_.close();
  decoder_.restart_stream();
  ++stats_.disconnects;
  disconnected_at_ = Clock::now();
  next_retry_ = disconnected_at_ + retry_interval_;
}

void SerialSource::give_up_if_gone(Clock::time_point now) {
  if (now - disconnected_at_ < give_up_after_) return;
  char gone[32];
  std::snprintf(gone, sizeof gone, "%g s", 1e-3 * static_cast<double>(give_up_after_.count()));
  fail(description() + ": disconnected for " + gone + " and not back (the last try: " + disconnect_reason_ + ")");
}

void SerialSource::fail(std::string why) {
  failed_ = true;
  failure_ = std::move(why);
  throw IoError(failure_);
}

bool SerialSource::try_reconnect(Clock::time_point now) {
  if (now < next_retry_) return false;
  next_retry_ = now + retry_interval_;
  if (!port_.try_open(path_, baud_)) {
    disconnect_reason_ = port_.error();
    return false;
  }
  ++stats_.reconnects;
  return true;
}

void SerialSource::push(const RawFrame& raw, Clock::time_point received) {
  if (raw.electrode_count != electrode_count_)
    fail(description() + ": the board sends frames of " + std::to_string(raw.electrode_count) +
         " electrodes but the sensor has " + std::to_string(electrode_count_));
  if (queue_size_ == queue_.size()) {  // the consumer fell behind: drop the oldest
    queue_head_ = (queue_head_ + 1) % queue_.size();
    --queue_size_;
    ++stats_.overruns;
  }
  SourceFrame& slot = queue_[(queue_head_ + queue_size_) % queue_.size()];
  ++queue_size_;
  to_volts(raw, vref_V_, slot.volts);
  slot.raw = raw;  // N·N counts into a slot sized for them: no allocation
  slot.sequence = raw.sequence;
  slot.board_time_s = clock_.seconds(raw.timestamp_us);
  slot.received = received;
}

bool SerialSource::pop(SourceFrame& frame) {
  if (queue_size_ == 0) return false;
  SourceFrame& slot = queue_[queue_head_];
  // No copy: the caller's old buffer becomes the slot's. Sized first (once, on the caller's first
  // frame), so every slot stays N×N and to_volts never reallocates.
  if (frame.volts.rows() != electrode_count_ || frame.volts.cols() != electrode_count_)
    frame.volts.resize(electrode_count_, electrode_count_);
  frame.raw.counts.resize(slot.raw.counts.size());
  frame.volts.swap(slot.volts);
  std::swap(frame.raw, slot.raw);
  frame.sequence = slot.sequence;
  frame.board_time_s = slot.board_time_s;
  frame.received = slot.received;
  queue_head_ = (queue_head_ + 1) % queue_.size();
  --queue_size_;
  return true;
}

}  // namespace emit
