#include "emit/io/mcap_writer.hpp"

#include <zlib.h>

#include <cstring>

#include "emit/core/version.hpp"

namespace emit {

namespace {

constexpr std::uint8_t magic[8] = {0x89, 'M', 'C', 'A', 'P', '0', '\r', '\n'};
enum Opcode : std::uint8_t {
  header_op = 0x01,
  footer_op = 0x02,
  schema_op = 0x03,
  channel_op = 0x04,
  message_op = 0x05,
  data_end_op = 0x0F
};

/// Little-endian fields and length-prefixed strings, as the format's records hold them.
class Fields {
 public:
  explicit Fields(std::vector<std::uint8_t>& out) : out_(out) { out_.clear(); }
  template <typename T>
  Fields& put(T value) {
    const std::size_t at = out_.size();
    out_.resize(at + sizeof(T));
    std::memcpy(out_.data() + at, &value, sizeof(T));  // little-endian hosts (x86-64, ARM)
    return *this;
  }
  Fields& string(std::string_view text) {  // uint32 length, then the bytes
    put(static_cast<std::uint32_t>(text.size()));
    out_.insert(out_.end(), text.begin(), text.end());
    return *this;
  }

 private:
  std::vector<std::uint8_t>& out_;
};

}  // namespace

McapWriter::McapWriter(OutputFile file, std::string_view profile)
    : file_(std::move(file)), crc_(static_cast<std::uint32_t>(crc32(0, nullptr, 0))) {
  write(magic, sizeof magic);
  Fields(scratch_).string(profile).string(std::string("emit ") + version());
  record(header_op, scratch_);
}

McapWriter::McapWriter(const std::string& path, std::string_view profile)
    : McapWriter(OutputFile({"", path}, {.partial = true}), profile) {}

McapWriter::~McapWriter() = default;  // the stream closes; PATH.partial stays as it is

std::uint16_t McapWriter::add_schema(std::string_view name, std::string_view encoding, std::string_view data) {
  const std::uint16_t id = ++schemas_;  // 0 is "no schema" in the format
  Fields(scratch_).put(id).string(name).string(encoding).string(data);
  record(schema_op, scratch_);
  return id;
}

std::uint16_t McapWriter::add_channel(std::uint16_t schema_id, std::string_view topic,
                                      std::string_view message_encoding) {
  const std::uint16_t id = channels_++;
  Fields(scratch_).put(id).put(schema_id).string(topic).string(message_encoding).put(std::uint32_t{0});  // no metadata
  record(channel_op, scratch_);
  return id;
}

void McapWriter::write_message(std::uint16_t channel_id, std::uint32_t sequence, std::uint64_t log_time_ns,
                               std::uint64_t publish_time_ns, std::span<const std::uint8_t> data) {
  std::uint8_t head[1 + 8 + 2 + 4 + 8 + 8];
  const std::uint64_t length = 2 + 4 + 8 + 8 + data.size();
  head[0] = message_op;
  std::memcpy(head + 1, &length, 8);
  std::memcpy(head + 9, &channel_id, 2);
  std::memcpy(head + 11, &sequence, 4);
  std::memcpy(head + 15, &log_time_ns, 8);
  std::memcpy(head + 23, &publish_time_ns, 8);
  write(head, sizeof head);
  write(data.data(), data.size());
  check();
}

void McapWriter::close() { end(/*rename=*/true); }
void McapWriter::close_partial() { end(/*rename=*/false); }

void McapWriter::end(bool rename) {
  if (closed_) return;
  closed_ = true;
  Fields(scratch_).put(crc_);  // the data section's CRC-32: every byte before the Data End record
  record(data_end_op, scratch_);
  Fields(scratch_).put(std::uint64_t{0}).put(std::uint64_t{0}).put(std::uint32_t{0});  // no summary
  record(footer_op, scratch_);
  write(magic, sizeof magic);
  if (rename) file_.commit();
  else file_.finish();
}

void McapWriter::record(std::uint8_t opcode, std::span<const std::uint8_t> content) {
  const std::uint64_t length = content.size();
  write(&opcode, 1);
  write(&length, 8);
  write(content.data(), content.size());
  check();
}

void McapWriter::write(const void* bytes, std::size_t size) {
  file_.stream().write(static_cast<const char*>(bytes), static_cast<std::streamsize>(size));
  crc_ = static_cast<std::uint32_t>(crc32(crc_, static_cast<const Bytef*>(bytes), static_cast<uInt>(size)));
}

void McapWriter::check() const { file_.check(); }

}  // namespace emit
