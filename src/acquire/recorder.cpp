#include "emit/acquire/recorder.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>

#include "emit/acquire/recording.hpp"
#include "emit/core/errors.hpp"

namespace emit {
namespace fw = emit::firmware;

Recorder::Recorder(const std::string& path, const Sensor& sensor)
    : Recorder(OutputFile({"", path}, {.partial = true}), sensor) {}

Recorder::Recorder(OutputFile file, const Sensor& sensor)
    : file_(std::move(file)), electrode_count_(sensor.electrode_count()), packet_(fw::packet_size(electrode_count_)) {
  RecordingHeader header;
  header.electrode_count = electrode_count_;
  header.adc_bits = sensor.adc.bits;
  header.vref_V = sensor.adc.vref_V;
  header.start_unix_us = static_cast<std::uint64_t>(
      std::chrono::duration_cast<std::chrono::microseconds>(std::chrono::system_clock::now().time_since_epoch())
          .count());
  std::array<std::uint8_t, recording_header_size> bytes{};
  encode_recording_header(header, bytes.data());
  file_.stream().write(reinterpret_cast<const char*>(bytes.data()), static_cast<std::streamsize>(bytes.size()));
  file_.check();
}

Recorder::~Recorder() {
  try {
    close();
  } catch (const std::exception&) {  // PATH.partial stays for the user to look at
  }
}

void Recorder::record(const RawFrame& frame) {
  if (frame.electrode_count != electrode_count_)
    throw InvalidInput(path() + ": cannot record a frame of " + std::to_string(frame.electrode_count) +
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
  if (closed_) throw IoError(path() + ": the recording is closed");
  const std::size_t size = fw::encode_packet(header, counts, packet_.data(), packet_.size());
  if (size != packet_.size()) throw InvalidInput(path() + ": a frame with an impossible packet header");
  file_.stream().write(reinterpret_cast<const char*>(packet_.data()), static_cast<std::streamsize>(size));
  file_.check();
  ++frames_;
}

void Recorder::close() {
  if (closed_) return;
  closed_ = true;
  file_.commit();
}

void Recorder::close_partial() {
  if (closed_) return;
  closed_ = true;
  file_.finish();
}

}  // namespace emit
