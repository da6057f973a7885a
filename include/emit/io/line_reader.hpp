#pragma once
/// \file line_reader.hpp
/// The lines of a text file, read with a bound: a line longer than the bound is an error naming the
/// file and line, so a binary file or /dev/zero is never read into memory whole. A UTF-8 byte-order
/// mark before the first line is skipped and "\r\n" endings are accepted (files from Windows and
/// spreadsheets).
///
/// Example:
///
///     LineReader lines(path, "frames file");
///     for (std::string line; lines.next(line);) parse(line, lines.where());
#include <cstddef>
#include <fstream>
#include <string>
#include <vector>

namespace emit {

class LineReader {
 public:
  static constexpr std::size_t default_max_line_bytes = std::size_t{1} << 20;  // 1 MiB

  /// \param what  what the file is, for the open error ("frames file").
  /// \throw IoError "<path>: cannot open <what> (<reason>)".
  LineReader(std::string path, const std::string& what, std::size_t max_line_bytes = default_max_line_bytes);

  /// The next line, without its end. \return false at the end of the file.
  /// \throw InvalidInput "<path>:<line>: line longer than <bound> (is this a <what>?)".
  bool next(std::string& line);

  int line_number() const { return line_number_; }  ///< of the line next() returned last
  std::string where() const { return path_ + ":" + std::to_string(line_number_); }  ///< "<path>:<line>"
  const std::string& path() const { return path_; }

 private:
  bool fill();  ///< more bytes into the buffer; false at the end of the file

  std::string path_, what_;
  std::size_t max_line_bytes_;
  std::ifstream in_;
  std::vector<char> buffer_;
  std::size_t begin_ = 0, end_ = 0;
  int line_number_ = 0;
};

}  // namespace emit
