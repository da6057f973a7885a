#include "emit/core/output_file.hpp"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <array>
#include <atomic>
#include <cerrno>
#include <csignal>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <streambuf>
#include <utility>
#include <vector>

#include "emit/core/errors.hpp"

namespace emit {

namespace fs = std::filesystem;

namespace {

// ---- The temporary files alive, for a signal handler to remove -----------------------------------

/// A slot holds a string from strdup, or null: a flag byte ('h' hidden: always removed; 'p'
/// partial: removed only while empty on disk), then the path. Claimed and released with atomic
/// exchanges (no lock a handler could wait on).
constexpr int slot_count = 64;
std::array<std::atomic<char*>, slot_count> temporary_paths{};

int register_temporary(const std::string& path, bool partial) {
  char* entry = ::strdup(((partial ? "p" : "h") + path).c_str());
  if (entry == nullptr) return -1;
  for (int slot = 0; slot < slot_count; ++slot) {
    char* expected = nullptr;
    if (temporary_paths[static_cast<std::size_t>(slot)].compare_exchange_strong(expected, entry)) return slot;
  }
  std::free(entry);  // more than slot_count at once: this one is not removed on a signal
  return -1;
}

void unregister_temporary(int& slot) {
  if (slot >= 0) std::free(temporary_paths[static_cast<std::size_t>(slot)].exchange(nullptr));
  slot = -1;
}

extern "C" void remove_temporaries_and_reraise(int signal_number) {
  for (auto& slot : temporary_paths) {
    const char* entry = slot.load();
    if (entry == nullptr) continue;
    struct stat status {};
    if (entry[0] == 'p' && ::stat(entry + 1, &status) == 0 && status.st_size > 0) continue;  // a recording's frames
    ::unlink(entry + 1);  // stat and unlink are async-signal-safe
  }
  std::signal(signal_number, SIG_DFL);
  std::raise(signal_number);
}

// ---- Where the bytes go -------------------------------------------------------------------------

/// The descriptor a path names: "-" (when it means standard output), /dev/stdin, /dev/stdout,
/// /dev/stderr, /dev/fd/N, /proc/self/fd/N, /proc/thread-self/fd/N. -1 for any other path.
int descriptor_number(const std::string& path, bool standard_output) {
  if (path == "-") return standard_output ? 1 : -1;
  const fs::path normal = fs::path(path).lexically_normal();
  if (normal == "/dev/stdin") return 0;
  if (normal == "/dev/stdout") return 1;
  if (normal == "/dev/stderr") return 2;
  const fs::path folder = normal.parent_path();
  const std::string name = normal.filename().string();
  if (folder != "/dev/fd" && folder != "/proc/self/fd" && folder != "/proc/thread-self/fd") return -1;
  if (name.empty() || name.size() > 9 || name.find_first_not_of("0123456789") != std::string::npos) return -1;
  return static_cast<int>(std::strtol(name.c_str(), nullptr, 10));  // at most 9 digits: an int
}

/// Bytes for a file descriptor, buffered; the first failed write's errno is kept, and what the
/// buffer held then is dropped (a line cut there must not reach the next reader of a FIFO).
class DescriptorBuffer : public std::streambuf {
 public:
  static constexpr std::size_t buffer_bytes = std::size_t{64} * 1024;

  DescriptorBuffer() : buffer_(buffer_bytes) { reset(); }
  void attach(int fd) {
    fd_ = fd;
    error_ = 0;
    reset();
  }
  /// The descriptor, given up without writing what is buffered (dropped).
  int release() {
    reset();
    return std::exchange(fd_, -1);
  }
  int fd() const { return fd_; }
  int error() const { return error_; }
  /// Writes what is buffered. \return false if this or an earlier write failed.
  bool drain() {
    if (error_ != 0) return false;
    if (fd_ < 0) error_ = EBADF;
    for (const char* next = pbase(); error_ == 0 && next < pptr();) {
      const ssize_t written = ::write(fd_, next, static_cast<std::size_t>(pptr() - next));
      if (written > 0) next += written;
      else error_ = written == 0 ? EIO : errno;  // EINTR too: a signal meant to stop a blocked write
    }
    reset();
    return error_ == 0;
  }

 protected:
  int_type overflow(int_type c) override {
    if (!drain()) return traits_type::eof();
    if (!traits_type::eq_int_type(c, traits_type::eof())) {
      *pptr() = traits_type::to_char_type(c);
      pbump(1);
    }
    return traits_type::not_eof(c);
  }
  int sync() override { return drain() ? 0 : -1; }

 private:
  void reset() { setp(buffer_.data(), buffer_.data() + buffer_.size()); }

  std::vector<char> buffer_;
  int fd_ = -1;
  int error_ = 0;
};

std::string error_text(int error) { return std::strerror(error); }

}  // namespace

OutputKind output_kind(const std::string& path, bool standard_output) {
  if (descriptor_number(path, standard_output) >= 0) return OutputKind::descriptor;
  struct stat status {};
  if (::stat(path.c_str(), &status) != 0) return OutputKind::file;  // not there yet (or a dangling link)
  if (S_ISREG(status.st_mode)) return OutputKind::file;
  if (S_ISDIR(status.st_mode)) return OutputKind::folder;
  if (S_ISFIFO(status.st_mode)) return OutputKind::fifo;
  return OutputKind::device;
}

std::string replaced_file(const std::string& path) {
  std::error_code error;
  if (!fs::is_symlink(path, error)) return path;
  const fs::path resolved = fs::canonical(path, error);
  return error ? path : resolved.string();
}

struct OutputFile::State {
  NamedPath target;
  OutputOptions options;
  OutputKind kind = OutputKind::file;
  std::string replaced;  ///< the file a rename replaces (a symlink resolved)
  std::string write_path;
  DescriptorBuffer buffer;
  std::ostream stream{&buffer};
  int slot = -1;  ///< in the registry of temporary files
  bool finished = false, committed = false;

  State(NamedPath target_, OutputOptions options_) : target(std::move(target_)), options(options_) {}
  State(const State&) = delete;
  State& operator=(const State&) = delete;

  std::string describe() const { return target.name.empty() ? target.path : target.name + " " + target.path; }

  void open_temporary() {
    replaced = replaced_file(target.path);
    const fs::path file(replaced);
    const fs::path folder = file.parent_path().empty() ? fs::path(".") : file.parent_path();
    std::error_code error;
    if (!fs::is_directory(folder, error))
      throw IoError(describe() + ": cannot write: folder " + folder.string() + " does not exist");
    if (options.partial) {
      write_path = replaced + ".partial";
    } else {                   // hidden, unique to this process, and with the target's extension
      std::string name = ".";  // appended, not "." + …: GCC 12 warns of a false overlap (-Wrestrict)
      name += file.stem().string();
      name += ".tmp" + std::to_string(::getpid());
      name += file.extension().string();
      write_path = (folder / name).string();
    }
    if (options.stream) {
      const int fd = ::open(write_path.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0666);
      if (fd < 0)
        throw IoError(describe() + (options.partial ? ": cannot create " + write_path : std::string(": cannot write")) +
                      " (" + error_text(errno) + ")");
      buffer.attach(fd);
    }
    slot = register_temporary(write_path, options.partial);  // last: a throw above leaves nothing to remove
  }

  void open_direct() {
    write_path = target.path;
    if (!options.stream) return;
    const int number = descriptor_number(target.path, options.standard_output);
    const int fd = number >= 0 ? ::fcntl(number, F_DUPFD_CLOEXEC, 3)
                               : ::open(target.path.c_str(), O_WRONLY | O_CLOEXEC | O_NOCTTY);
    if (fd < 0) throw IoError(describe() + ": cannot write (" + error_text(errno) + ")");
    buffer.attach(fd);
  }

  /// Flushes (unless `drop`) and closes the descriptor, if one is open. \return the first error, or 0.
  int close_descriptor(bool drop) {
    if (buffer.fd() < 0) return buffer.error();
    const bool written = drop || buffer.drain();
    const int error = written ? 0 : buffer.error();
    const int fd = buffer.release();
    if (fd >= 0 && ::close(fd) != 0 && error == 0 && errno != EINTR) return errno;
    return error;
  }

  ~State() {
    if (committed) return;
    if (kind != OutputKind::file) {
      close_descriptor(/*drop=*/true);  // a pipe's reader may not read: never wait here
      return;
    }
    close_descriptor(/*drop=*/!options.partial);
    struct stat status {};
    const bool keep = options.partial && ::stat(write_path.c_str(), &status) == 0 && status.st_size > 0;
    if (!keep) ::unlink(write_path.c_str());
    unregister_temporary(slot);
  }
};

OutputFile::OutputFile() = default;

OutputFile::OutputFile(NamedPath target, OutputOptions options)
    : state_(std::make_unique<State>(std::move(target), options)) {
  State& s = *state_;
  s.kind = output_kind(s.target.path, options.standard_output);
  if (s.kind == OutputKind::folder) throw IoError(s.describe() + ": cannot write: it is a folder");
  if (s.kind == OutputKind::file) s.open_temporary();
  else s.open_direct();
}

OutputFile::~OutputFile() = default;
OutputFile::OutputFile(OutputFile&&) noexcept = default;
OutputFile& OutputFile::operator=(OutputFile&&) noexcept = default;

OutputKind OutputFile::kind() const { return state_->kind; }
const std::string& OutputFile::path() const { return state_->target.path; }
std::string OutputFile::describe() const { return state_->describe(); }
const std::string& OutputFile::write_path() const { return state_->write_path; }
std::ostream& OutputFile::stream() { return state_->stream; }
bool OutputFile::reader_gone() const { return state_->buffer.error() == EPIPE; }

void OutputFile::check() const {
  if (const int error = state_->buffer.error(); error != 0)
    throw IoError(describe() + ": write failed (" + error_text(error) + ")");
}

bool OutputFile::clear_interrupted() {
  State& s = *state_;
  if (s.buffer.error() != EINTR) return false;
  s.buffer.attach(s.buffer.fd());
  s.stream.clear();
  return true;
}

bool OutputFile::reconnect() {
  State& s = *state_;
  if (s.kind != OutputKind::fifo || s.finished) return false;
  if (s.buffer.fd() >= 0 && s.buffer.error() == 0) return true;
  if (const int old = s.buffer.release(); old >= 0) ::close(old);
  // Without waiting: a FIFO no one has open for reading refuses a non-blocking writer (ENXIO).
  const int fd = ::open(s.target.path.c_str(), O_WRONLY | O_NONBLOCK | O_CLOEXEC | O_NOCTTY);
  if (fd < 0) return false;
  ::fcntl(fd, F_SETFL, ::fcntl(fd, F_GETFL) & ~O_NONBLOCK);  // then it waits for a slow reader, as before
  s.buffer.attach(fd);
  s.stream.clear();
  return true;
}

void OutputFile::finish() {
  State& s = *state_;
  if (s.finished) return;
  s.finished = true;
  if (const int error = s.close_descriptor(/*drop=*/false); error != 0)
    throw IoError(describe() + ": write failed (" + error_text(error) + ")");
}

void OutputFile::commit() {
  State& s = *state_;
  if (s.committed) return;
  finish();
  if (s.kind == OutputKind::file && std::rename(s.write_path.c_str(), s.replaced.c_str()) != 0)
    throw IoError(describe() + ": cannot replace file (" + error_text(errno) + ")");
  s.committed = true;
  unregister_temporary(s.slot);
}

void remove_temporary_files_on_signals() {
  for (const int signal_number : {SIGINT, SIGTERM, SIGHUP}) std::signal(signal_number, remove_temporaries_and_reraise);
}

}  // namespace emit
