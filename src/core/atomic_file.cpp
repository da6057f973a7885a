#include "emit/core/atomic_file.hpp"

#include <unistd.h>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>

#include "emit/core/errors.hpp"

namespace emit {

AtomicFile::AtomicFile(std::string path, bool open_stream) : path_(std::move(path)) {
  const std::filesystem::path target(path_);
  const auto folder = target.parent_path().empty() ? std::filesystem::path(".") : target.parent_path();
  if (!std::filesystem::is_directory(folder))
    throw IoError(path_ + ": cannot write: folder " + folder.string() + " does not exist");
  // Hidden, unique to this process, and with the target's extension.
  std::string name = ".";
  name += target.stem().string();
  name += ".tmp" + std::to_string(::getpid());
  name += target.extension().string();
  temp_path_ = (folder / name).string();
  if (open_stream) {
    stream_.open(temp_path_, std::ios::binary | std::ios::trunc);
    if (!stream_) throw IoError(path_ + ": cannot write (" + std::strerror(errno) + ")");
  }
}

AtomicFile::~AtomicFile() {
  if (!committed_) {
    if (stream_.is_open()) stream_.close();
    std::remove(temp_path_.c_str());
  }
}

void AtomicFile::commit() {
  if (stream_.is_open()) {
    stream_.flush();
    if (!stream_) throw IoError(path_ + ": write failed (disk full?)");
    stream_.close();
  }
  if (std::rename(temp_path_.c_str(), path_.c_str()) != 0)
    throw IoError(path_ + ": cannot replace file (" + std::strerror(errno) + ")");
  committed_ = true;
}

}  // namespace emit
