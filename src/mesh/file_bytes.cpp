#include "file_bytes.hpp"

#include <algorithm>
#include <cerrno>
#include <cstring>

#include "emit/core/errors.hpp"

namespace emit::detail {

namespace {
constexpr std::size_t block_bytes = 1 << 16;
}  // namespace

FileBytes::FileBytes(const std::string& path, const std::string& file) : name_(file), block_(block_bytes) {
  file_ = std::fopen(path.c_str(), "rb");
  if (file_ == nullptr) throw IoError(file + ": cannot open (" + std::strerror(errno) + ")");
  if (std::fseek(file_, 0, SEEK_END) == 0) {
    const long end = std::ftell(file_);
    if (end > 0) size_ = static_cast<std::uint64_t>(end);
  }
  std::rewind(file_);
}

FileBytes::~FileBytes() {
  if (file_ != nullptr) std::fclose(file_);
}

bool FileBytes::fill() {
  if (begin_ < end_) return true;
  begin_ = 0;
  end_ = std::fread(block_.data(), 1, block_.size(), file_);
  if (end_ == 0 && std::ferror(file_)) throw IoError(name_ + ": cannot read (" + std::strerror(errno) + ")");
  return end_ > 0;
}

bool FileBytes::line(std::string& out, std::size_t max_bytes, bool& too_long) {
  out.clear();
  too_long = false;
  if (!fill()) return false;
  ++line_number_;
  while (fill()) {
    const char* from = block_.data() + begin_;
    const char* newline = static_cast<const char*>(std::memchr(from, '\n', end_ - begin_));
    const std::size_t run = newline != nullptr ? static_cast<std::size_t>(newline - from) : end_ - begin_;
    const std::size_t kept = std::min(run, max_bytes - std::min(max_bytes, out.size()));
    out.append(from, kept);
    if (kept < run) too_long = true;
    const std::size_t consumed = run + (newline != nullptr ? 1 : 0);
    begin_ += consumed;
    offset_ += consumed;
    if (newline != nullptr) break;
  }
  return true;
}

bool FileBytes::read(void* out, std::size_t count) {
  auto* to = static_cast<char*>(out);
  while (count > 0) {
    if (!fill()) return false;
    const std::size_t run = std::min(count, end_ - begin_);
    std::memcpy(to, block_.data() + begin_, run);
    to += run;
    count -= run;
    begin_ += run;
    offset_ += run;
  }
  return true;
}

bool FileBytes::skip(std::uint64_t count) {
  while (count > 0) {
    if (!fill()) return false;
    const std::size_t run = static_cast<std::size_t>(std::min<std::uint64_t>(count, end_ - begin_));
    count -= run;
    begin_ += run;
    offset_ += run;
  }
  return true;
}

bool FileBytes::at_end() { return !fill(); }

}  // namespace emit::detail
