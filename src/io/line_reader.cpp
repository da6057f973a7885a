#include "emit/io/line_reader.hpp"

#include <cerrno>
#include <cstring>

#include "emit/core/errors.hpp"

namespace emit {

LineReader::LineReader(std::string path, const std::string& what, std::size_t max_line_bytes)
    : path_(std::move(path)), what_(what), max_line_bytes_(max_line_bytes), buffer_(std::size_t{1} << 16) {
  in_.open(path_, std::ios::binary);
  if (!in_) throw IoError(path_ + ": cannot open " + what + " (" + std::strerror(errno) + ")");
}

bool LineReader::fill() {
  in_.read(buffer_.data(), static_cast<std::streamsize>(buffer_.size()));
  begin_ = 0;
  end_ = static_cast<std::size_t>(in_.gcount());
  if (in_.bad()) throw IoError(path_ + ": read failed (" + std::strerror(errno) + ")");
  return end_ > 0;
}

bool LineReader::next(std::string& line) {
  line.clear();
  bool any = false;  // a last line without "\n" still counts
  while (true) {
    if (begin_ == end_ && !fill()) {
      if (!any) return false;
      break;
    }
    any = true;
    const char* start = buffer_.data() + begin_;
    const auto* newline = static_cast<const char*>(std::memchr(start, '\n', end_ - begin_));
    const std::size_t length = newline != nullptr ? static_cast<std::size_t>(newline - start) : end_ - begin_;
    if (line.size() + length > max_line_bytes_)
      throw InvalidInput(path_ + ":" + std::to_string(line_number_ + 1) + ": line longer than " +
                         std::to_string(max_line_bytes_ >> 10) + " KiB (is this a " + what_ + "?)");
    line.append(start, length);
    begin_ += length;
    if (newline != nullptr) {
      ++begin_;
      break;
    }
  }
  ++line_number_;
  if (line_number_ == 1 && line.rfind("\xef\xbb\xbf", 0) == 0) line.erase(0, 3);
  if (!line.empty() && line.back() == '\r') line.pop_back();
  return true;
}

}  // namespace emit
