#include "emit/acquire/recorder.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <filesystem>

#include "emit/acquire/recording.hpp"
#include "emit/core/errors.hpp"

namespace emit {
namespace fw = emit::firmware;

Recorder::Recorder(std::string path, const Sensor& sensor)
    : path_(std::move(path)),
      partial_path_(path_ + ".partial"),
      electrode_count_(sensor.electrode_count()),
      packet_(fw::packet_size(electrode_count_)) {
  stream_.open(partial_path_, std::ios::binary | std::ios::trunc);
  if (!stream_) throw IoError(partial_path_ + ": cannot create the recording");
  RecordingHeader header;
  header.electrode_count = electrode_count_;
  header.adc_bits = sensor.adc.bits;
  header.vref_V = sensor.adc.vref_V;
  header.start_unix_us = static_cast<std::uint64_t>(
      std::chrono::duration_cast<std::chrono::microseconds>(std::chrono::system_clock::now().time_since_epoch())
          .count());
  std::array<std::uint8_t, recording_header_size> bytes{};
  encode_recording_header(header, bytes.data());
  stream_.write(reinterpret_cast<const char*>(bytes.data()), static_cast<std::streamsize>(bytes.size()));
  if (!stream_) throw IoError(partial_path_ + ": cannot write the recording's header");
}

Recorder::~Recorder() {
  try {
    close();
  } catch (const std::exception&) {  // PATH.partial stays for the user to look at
  }
}

void Recorder::record(const RawFrame& frame) {
  if (frame.electrode_count != electrode_count_)
    throw InvalidInput(path_ + ": cannot record a frame of " + std::to_string(frame.electrode_count) +
                       " electrodes; the recording has " + std::to_string(electrode_count_));
  fw::PacketHeader header;
  header.electrode_count = static_cast<std::uint8_t>(frame.electrode_count);
  header.adc_bits = static_cast<std::uint8_t>(frame.adc_bits);
  header.oversampling = static_cast<std::uint8_t>(frame.oversampling);
  header.sequence = frame.sequence;
  header.timestamp_us = frame.timestamp_us;
  write_packet(header, frame.counts.data());
}

void Recorder::write_packet(const fw::PacketHeader& header, const std::uint16_t* counts) {
  if (closed_) throw IoError(path_ + ": the recording is closed");
  const std::size_t size = fw::encode_packet(header, counts, packet_.data(), packet_.size());
  if (size != packet_.size()) throw InvalidInput(path_ + ": a frame with an impossible packet header");
  stream_.write(reinterpret_cast<const char*>(packet_.data()), static_cast<std::streamsize>(size));
  if (!stream_) throw IoError(partial_path_ + ": write failed (disk full?)");
  ++frames_;
}

void Recorder::close() {
  if (closed_) return;
  closed_ = true;
  stream_.close();
  if (!stream_) throw IoError(partial_path_ + ": could not finish writing the recording");
  std::error_code ec;
  std::filesystem::rename(partial_path_, path_, ec);
  if (ec) throw IoError(partial_path_ + ": cannot rename to " + path_ + ": " + ec.message());
}

}  // namespace emit
