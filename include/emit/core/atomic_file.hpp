#pragma once
/// \file atomic_file.hpp
/// Write-then-rename: output goes to a temporary file beside the target and replaces it only on
/// commit(), so an error half-way never leaves a half file over a good one.
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
};

}  // namespace emit
