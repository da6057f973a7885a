#include "emit/core/atomic_file.hpp"

#include <unistd.h>
#include <array>
#include <atomic>
#include <cerrno>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>

#include "emit/core/errors.hpp"

namespace emit {

namespace {

/// The temporary files alive, as C strings a signal handler can unlink: a slot holds a path from
/// strdup, or null. Claimed and released with atomic exchanges (no lock a handler could wait on).
constexpr int slot_count = 64;
std::array<std::atomic<char*>, slot_count> temporary_paths{};

int register_temporary(const std::string& path) {
  char* copy = ::strdup(path.c_str());
  if (copy == nullptr) return -1;
  for (int slot = 0; slot < slot_count; ++slot) {
    char* expected = nullptr;
    if (temporary_paths[static_cast<std::size_t>(slot)].compare_exchange_strong(expected, copy)) return slot;
  }
  std::free(copy);  // more than slot_count at once: this one is not removed on a signal
  return -1;
}

void unregister_temporary(int slot) {
  if (slot >= 0) std::free(temporary_paths[static_cast<std::size_t>(slot)].exchange(nullptr));
}

extern "C" void remove_temporaries_and_reraise(int signal_number) {
  for (auto& slot : temporary_paths)
    if (const char* path = slot.load(); path != nullptr) ::unlink(path);  // async-signal-safe
  std::signal(signal_number, SIG_DFL);
  std::raise(signal_number);
}

}  // namespace

void remove_temporary_files_on_signals() {
  for (const int signal_number : {SIGINT, SIGTERM, SIGHUP}) std::signal(signal_number, remove_temporaries_and_reraise);
}

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
  slot_ = register_temporary(temp_path_);  // last: a constructor that throws runs no destructor
}

AtomicFile::~AtomicFile() {
  if (!committed_) {
    if (stream_.is_open()) stream_.close();
    std::remove(temp_path_.c_str());
  }
  unregister_temporary(slot_);
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
  unregister_temporary(slot_);
  slot_ = -1;
}

}  // namespace emit
