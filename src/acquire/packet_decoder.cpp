#include "emit/acquire/packet_decoder.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <string>

#include "core/frame_packet.hpp"
#include "emit/core/errors.hpp"

namespace emit {
namespace fw = emit::firmware;

PacketDecoder::PacketDecoder() : buffer_(fw::packet_max_size) {
  frame_.counts.reserve(static_cast<std::size_t>(fw::packet_max_electrodes) * fw::packet_max_electrodes);
}

void PacketDecoder::restart_stream() {
  begin_ = end_ = 0;
  have_sequence_ = false;
}

std::size_t PacketDecoder::push(std::span<const std::uint8_t> bytes) {
  if (begin_ > 0) {  // move the kept bytes (less than one packet) to the front
    std::memmove(buffer_.data(), buffer_.data() + begin_, end_ - begin_);
    end_ -= begin_;
    begin_ = 0;
  }
  const std::size_t count = std::min(bytes.size(), buffer_.size() - end_);
  std::memcpy(buffer_.data() + end_, bytes.data(), count);
  end_ += count;
  return count;
}

const RawFrame* PacketDecoder::next_frame() {
  for (;;) {
    const std::uint8_t* bytes = buffer_.data() + begin_;
    const std::size_t available = end_ - begin_;
    // The first "EM", or a final lone 'E' that may be the start of one.
    std::size_t sync = 0;
    while (sync < available &&
           !(bytes[sync] == fw::packet_sync0 && (sync + 1 == available || bytes[sync + 1] == fw::packet_sync1)))
      ++sync;
    stats_.garbage_bytes += sync;
    begin_ += sync;
    std::size_t size = 0;
    switch (try_decode(bytes + sync, available - sync, &size)) {
      case Verdict::need_more: return nullptr;
      case Verdict::rejected:
        ++stats_.corrupt;
        begin_ += 2;  // search again from the byte after the sync
        break;
      case Verdict::accepted:
        ++stats_.frames;
        begin_ += size;
        return &frame_;
    }
  }
}

PacketDecoder::Verdict PacketDecoder::try_decode(const std::uint8_t* bytes, std::size_t available, std::size_t* size) {
  if (available < fw::packet_header_size) return Verdict::need_more;
  fw::PacketHeader header;
  header.electrode_count = bytes[3];
  header.adc_bits = bytes[4];
  header.oversampling = bytes[5];
  const int n = header.electrode_count;
  if (bytes[2] != fw::packet_version || !fw::packet_header_valid(header) || fw::load_u16_le(bytes + 6) != 2 * n * n)
    return Verdict::rejected;
  *size = fw::packet_size(n);
  if (available < *size) return Verdict::need_more;
  const std::size_t crc_offset = *size - fw::packet_crc_size;
  if (fw::crc32(bytes + 2, crc_offset - 2) != fw::load_u32_le(bytes + crc_offset)) return Verdict::rejected;
  const std::size_t values = static_cast<std::size_t>(n) * static_cast<std::size_t>(n);
  const std::uint8_t* payload = bytes + fw::packet_header_size;
  const std::uint32_t limit = 1u << header.adc_bits;
  for (std::size_t i = 0; i < values; ++i)
    if (fw::load_u16_le(payload + 2 * i) >= limit) return Verdict::rejected;

  frame_.sequence = fw::load_u32_le(bytes + 8);
  frame_.timestamp_us = fw::load_u32_le(bytes + 12);
  frame_.electrode_count = n;
  frame_.adc_bits = header.adc_bits;
  frame_.oversampling = header.oversampling;
  frame_.counts.resize(values);  // within the reserved capacity
  for (std::size_t i = 0; i < values; ++i) frame_.counts[i] = fw::load_u16_le(payload + 2 * i);
  count_sequence(frame_.sequence);
  return Verdict::accepted;
}

void PacketDecoder::count_sequence(std::uint32_t sequence) {
  if (have_sequence_) {
    const std::uint32_t gap = sequence - last_sequence_ - 1u;  // modulo 2^32: wrap-around aware
    if (gap < 0x80000000u) stats_.dropped += gap;              // else behind: the board restarted
  }
  have_sequence_ = true;
  last_sequence_ = sequence;
}

void to_volts(const RawFrame& frame, double vref_V, Frame& volts) {
  if (!(std::isfinite(vref_V) && vref_V > 0))
    throw InvalidInput("to_volts: vref_V must be positive and finite, got " + std::to_string(vref_V));
  const int n = frame.electrode_count;
  if (n < 1 || frame.counts.size() != static_cast<std::size_t>(n) * static_cast<std::size_t>(n))
    throw InvalidInput("to_volts: frame " + std::to_string(frame.sequence) + " has " +
                       std::to_string(frame.counts.size()) + " counts for " + std::to_string(n) + " electrodes");
  if (frame.adc_bits < 1 || frame.adc_bits > fw::packet_max_adc_bits)
    throw InvalidInput("to_volts: frame " + std::to_string(frame.sequence) + " has adc_bits " +
                       std::to_string(frame.adc_bits) + ", expected 1..16");
  if (volts.rows() != n || volts.cols() != n) volts.resize(n, n);
  const double volts_per_count = vref_V / static_cast<double>((1u << frame.adc_bits) - 1u);
  for (std::size_t i = 0; i < frame.counts.size(); ++i) volts.data()[i] = frame.counts[i] * volts_per_count;
}

Frame to_volts(const RawFrame& frame, double vref_V) {
  Frame volts;
  to_volts(frame, vref_V, volts);
  return volts;
}

}  // namespace emit
