#include "emit/acquire/file_source.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <filesystem>
#include <thread>

#include "core/frame_packet.hpp"
#include "emit/core/errors.hpp"

namespace emit {
namespace fw = emit::firmware;
using Clock = std::chrono::steady_clock;

namespace {
/// Between passes when the recording cannot say (one frame, or all stamped alike): 50 frames/s,
/// the simulator's default pace.
constexpr std::uint32_t fallback_interval_us = 20'000;
}  // namespace

FileSource::FileSource(std::string path, const Sensor& sensor, bool as_fast_as_possible, bool loop)
    : path_(std::move(path)), as_fast_as_possible_(as_fast_as_possible), loop_(loop) {
  stream_.open(path_, std::ios::binary);
  if (!stream_) throw IoError(path_ + ": cannot open the recording");
  std::error_code ec;
  const std::uintmax_t size = std::filesystem::file_size(path_, ec);
  if (ec) throw IoError(path_ + ": cannot read the recording's size: " + ec.message());
  std::array<std::uint8_t, recording_header_size> bytes{};
  if (size < bytes.size())
    throw InvalidInput(path_ + ": not an emit recording (" + std::to_string(size) + " bytes, shorter than its header)");
  stream_.read(reinterpret_cast<char*>(bytes.data()), static_cast<std::streamsize>(bytes.size()));
  if (!stream_) throw IoError(path_ + ": cannot read the recording's header");
  header_ = decode_recording_header(bytes.data(), path_);
  if (header_.electrode_count != sensor.electrode_count())
    throw InvalidInput(path_ + ": recorded with " + std::to_string(header_.electrode_count) +
                       " electrodes, but the sensor has " + std::to_string(sensor.electrode_count()));
  const std::size_t packet_bytes = fw::packet_size(header_.electrode_count);
  const std::uintmax_t body = size - bytes.size();
  frame_count_ = body / packet_bytes;
  cut_bytes_ = body % packet_bytes;  // a recording cut mid-packet: its whole frames first, then the error
  packet_.resize(packet_bytes);
  pending_.volts.resize(header_.electrode_count, header_.electrode_count);
}

std::string FileSource::description() const {
  return "file:" + path_ + " (" + std::to_string(frame_count_) + " frames" +
         (cut_bytes_ > 0 ? " and a cut one, " : ", ") +
         (as_fast_as_possible_ ? "as fast as possible" : "at the recorded pace") + (loop_ ? ", in a loop)" : ")");
}

void FileSource::rewind() {
  if (pass_ == 0) {  // the mean interval of the first pass, on the unwrapped clock, in whole µs
    const double span_s = last_board_time_s_ - first_board_time_s_;
    const double mean_us = frame_count_ > 1 ? 1e6 * span_s / static_cast<double>(frame_count_ - 1) : 0;
    loop_interval_us_ =
        mean_us >= 1 ? static_cast<std::uint32_t>(std::llround(std::min(mean_us, 1e9))) : fallback_interval_us;
  }
  ++pass_;
  // The next pass's first packet gets the last one's number + 1 and its time + the interval.
  sequence_offset_ = last_sequence_ + 1u - first_sequence_;
  timestamp_offset_us_ = last_timestamp_us_ + loop_interval_us_ - first_timestamp_us_;
  frames_read_ = 0;
  stream_.clear();
  stream_.seekg(static_cast<std::streamoff>(recording_header_size));
  if (!stream_) throw IoError(path_ + ": cannot go back to the recording's first frame");
}

bool FileSource::read_pending() {
  if (frames_read_ == frame_count_ && cut_bytes_ > 0)
    throw IoError(path_ + ": truncated: frame " + std::to_string(frame_count_) + " (byte " +
                  std::to_string(recording_header_size + frame_count_ * packet_.size()) + ") has " +
                  std::to_string(cut_bytes_) + " of its " + std::to_string(packet_.size()) + " bytes");
  if (frames_read_ == frame_count_) {
    if (!loop_ || frame_count_ == 0) return false;
    rewind();
  }
  const std::uint64_t index = frames_read_++;
  stream_.read(reinterpret_cast<char*>(packet_.data()), static_cast<std::streamsize>(packet_.size()));
  if (!stream_) throw IoError(path_ + ": read failed at frame " + std::to_string(index));
  decoder_.restart_stream();  // each packet on its own: a bad one must not swallow the next
  bool decoded = false;
  decoder_.feed(packet_, [&](const RawFrame& raw) {
    to_volts(raw, header_.vref_V, pending_.volts);
    pending_.raw = raw;
    if (pass_ == 0 && index == 0) {
      first_sequence_ = raw.sequence;
      first_timestamp_us_ = raw.timestamp_us;
    }
    pending_.raw.sequence = raw.sequence + sequence_offset_;  // modulo 2^32, as the board's counters
    pending_.raw.timestamp_us = raw.timestamp_us + timestamp_offset_us_;
    last_sequence_ = pending_.raw.sequence;
    last_timestamp_us_ = pending_.raw.timestamp_us;
    pending_.sequence = pending_.raw.sequence;
    pending_.board_time_s = clock_.seconds(pending_.raw.timestamp_us);
    if (pass_ == 0 && index == 0) first_board_time_s_ = pending_.board_time_s;
    last_board_time_s_ = pending_.board_time_s;
    decoded = raw.electrode_count == header_.electrode_count;
  });
  if (!decoded)
    throw IoError(path_ + ": frame " + std::to_string(index) + " (byte " +
                  std::to_string(recording_header_size + index * packet_.size()) +
                  ") is not a valid packet (sync, header or CRC)");
  return true;
}

bool FileSource::next(SourceFrame& frame, std::chrono::milliseconds timeout) {
  if (finished_) throw IoError(path_ + ": end of recording");
  if (!have_pending_) {
    if (!read_pending()) {
      finished_ = true;
      throw IoError(path_ + ": end of recording");
    }
    have_pending_ = true;
  }
  if (!as_fast_as_possible_ && started_) {
    const auto due = start_ + std::chrono::duration_cast<Clock::duration>(
                                  std::chrono::duration<double>(pending_.board_time_s - t0_s_));
    if (due > Clock::now() + timeout) {
      std::this_thread::sleep_for(timeout);
      return false;
    }
    std::this_thread::sleep_until(due);
  }
  if (!started_) {
    started_ = true;
    start_ = Clock::now();
    t0_s_ = pending_.board_time_s;
  }
  frame.raw.counts.resize(pending_.raw.counts.size());  // so the buffer pending_ gets back holds a frame
  frame.volts.swap(pending_.volts);
  std::swap(frame.raw, pending_.raw);
  if (pending_.volts.rows() != header_.electrode_count)  // the caller's frame was empty
    pending_.volts.resize(header_.electrode_count, header_.electrode_count);
  frame.sequence = pending_.sequence;
  frame.board_time_s = pending_.board_time_s;
  frame.received = Clock::now();
  have_pending_ = false;
  // The last frame is out: a reader can stop without asking again (a loop goes on).
  finished_ = !loop_ && cut_bytes_ == 0 && frames_read_ >= frame_count_;
  return true;
}

}  // namespace emit
