#pragma once
/// \file mcap_writer.hpp
/// MCAP files (mcap.dev's format, version 0; ROS 2's bag format): the header, schemas, channels
/// and messages as they come, then the data section's end with its CRC-32 and the footer. Records
/// are written unchunked and without a summary section (both optional in the format), so a
/// message is on disk as soon as it is written and memory stays flat however long the recording.
///
/// Output goes to PATH.partial, renamed to PATH by close(). Without close() (an error, a crash),
/// PATH.partial stays as it got, a file cut mid-write that readers report as incomplete (it has no
/// footer), and PATH is never touched. A PATH that is not a regular file (a FIFO, a device) is
/// written directly (core/output_file.hpp).
///
/// Example:
///
///     emit::McapWriter mcap("run.mcap", "ros2");
///     const auto schema = mcap.add_schema("emit_msgs/msg/TactileState", "ros2msg", definition);
///     const auto channel = mcap.add_channel(schema, "/emit/frames", "cdr");
///     mcap.write_message(channel, sequence, time_ns, time_ns, cdr_bytes);
///     mcap.close();   // run.mcap.partial → run.mcap
#include <cstdint>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "emit/core/output_file.hpp"

namespace emit {

class McapWriter {
 public:
  /// Writes the magic and the header (`profile`: "ros2" for ROS 2 bags) into an output opened
  /// with OutputOptions::partial. \throw IoError naming it if the write fails.
  McapWriter(OutputFile file, std::string_view profile);
  /// Opens PATH (PATH.partial) first. \throw IoError naming the file when it cannot be created (a
  /// missing folder: before anything).
  McapWriter(const std::string& path, std::string_view profile);
  ~McapWriter();  ///< closes PATH.partial as it is, without renaming it
  McapWriter(const McapWriter&) = delete;
  McapWriter& operator=(const McapWriter&) = delete;

  /// \return the schema's id (1, 2, …). \throw IoError if the write fails.
  std::uint16_t add_schema(std::string_view name, std::string_view encoding, std::string_view data);
  /// \return the channel's id (0, 1, …). \throw IoError if the write fails.
  std::uint16_t add_channel(std::uint16_t schema_id, std::string_view topic, std::string_view message_encoding);
  /// A message on a channel; times in ns since the Unix epoch. Allocates nothing once warm.
  /// \throw IoError if the write fails.
  void write_message(std::uint16_t channel_id, std::uint32_t sequence, std::uint64_t log_time_ns,
                     std::uint64_t publish_time_ns, std::span<const std::uint8_t> data);
  /// Writes the data section's end (CRC-32 of everything before it), the footer and the closing
  /// magic, flushes, and renames PATH.partial to PATH. Later calls do nothing. \throw IoError.
  void close();
  /// close() but for the rename: a whole MCAP file of what was written stays at PATH.partial and
  /// PATH is untouched (a run that failed: `emit live`'s outputs). \throw IoError.
  void close_partial();

  const std::string& path() const { return file_.path(); }

 private:
  void record(std::uint8_t opcode, std::span<const std::uint8_t> content);
  void write(const void* bytes, std::size_t size);
  void check() const;     ///< \throw IoError if a write failed
  void end(bool rename);  ///< close() (rename) or close_partial()

  OutputFile file_;
  std::uint32_t crc_;  ///< zlib's running CRC-32 of all bytes so far
  std::vector<std::uint8_t> scratch_;
  std::uint16_t schemas_ = 0, channels_ = 0;
  bool closed_ = false;
};

}  // namespace emit
