#pragma once
// Private to mesh/: a file read forwards in lines of bounded length or in exact runs of bytes, a
// block at a time, for the checks that read a sheet's file before Gmsh does
// (mesh/stl_file_check.hpp, mesh/msh_file_check.hpp): memory does not grow with the file.
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <string>
#include <vector>

namespace emit::detail {

class FileBytes {
 public:
  /// Opens `path` to read. \throw IoError naming `file` (the path as messages quote it).
  FileBytes(const std::string& path, const std::string& file);
  ~FileBytes();
  FileBytes(const FileBytes&) = delete;
  FileBytes& operator=(const FileBytes&) = delete;

  /// The file's size in bytes when opened.
  std::uint64_t size() const { return size_; }
  /// Bytes consumed so far.
  std::uint64_t offset() const { return offset_; }
  /// Lines begun so far: the number of the line `line` returned last (from 1).
  std::int64_t line_number() const { return line_number_; }

  /// The next line, without its '\n' (a '\r' before it is kept): false at the end of the file.
  /// At most `max_bytes` of it are kept in `out`; `too_long` says whether there were more (they are
  /// consumed, unread).
  bool line(std::string& out, std::size_t max_bytes, bool& too_long);
  /// The next `count` bytes into `out`: false (and the rest consumed) if fewer are left.
  bool read(void* out, std::size_t count);
  /// Consume `count` bytes: false if fewer are left.
  bool skip(std::uint64_t count);
  /// Whether every byte has been consumed.
  bool at_end();

 private:
  bool fill();  ///< Refills the block when it is used up: false at the end of the file.
  std::FILE* file_ = nullptr;
  std::string name_;
  std::vector<char> block_;
  std::size_t begin_ = 0, end_ = 0;
  std::uint64_t size_ = 0, offset_ = 0;
  std::int64_t line_number_ = 0;
};

}  // namespace emit::detail
