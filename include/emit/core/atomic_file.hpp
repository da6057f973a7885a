#pragma once
/// \file atomic_file.hpp
/// Write-then-rename: output goes to a temporary file beside the target and replaces it only on
/// commit(), so an error half-way never leaves a half file over a good one. The temporary files
/// alive are registered, so a signal handler can remove them (remove_temporary_files_on_signals).
#include <fstream>
#include <string>

namespace emit {

class AtomicFile {
 public:
  /// Opens a temporary file in the target's folder, with the target's extension (some writers,
  /// such as Gmsh, choose the format from it). \throw IoError if it cannot be created.
  explicit AtomicFile(std::string path, bool open_stream = true);
  ~AtomicFile();  ///< removes the temporary file unless committed
  AtomicFile(const AtomicFile&) = delete;
  AtomicFile& operator=(const AtomicFile&) = delete;

  std::ofstream& stream() { return stream_; }
  const std::string& temp_path() const { return temp_path_; }
  /// Flush, close and rename over the target. \throw IoError on failure.
  void commit();

 private:
  std::string path_, temp_path_;
  std::ofstream stream_;
  bool committed_ = false;
  int slot_ = -1;  ///< in the registry of temporary files
};

/// SIGINT, SIGTERM and SIGHUP remove every AtomicFile's temporary file, then end the process as
/// the signal would have (the default action, re-raised). Handlers installed later (e.g. `emit
/// live`'s graceful stop) take precedence while they are installed.
void remove_temporary_files_on_signals();

}  // namespace emit
