#pragma once
/// \file atomic_file.hpp
/// OutputFile (core/output_file.hpp) by the name and constructor the Gmsh writer
/// (mesh/gmsh/msh_file.cpp) still uses: an unnamed output, with or without a stream; the same
/// rule (a temporary file renamed over a regular file, a device or FIFO written directly).
#include <string>
#include <utility>

#include "emit/core/output_file.hpp"

namespace emit {

class AtomicFile {
 public:
  /// \throw IoError as OutputFile's constructor.
  explicit AtomicFile(std::string path, bool open_stream = true)
      : file_({"", std::move(path)}, OutputOptions{.stream = open_stream}) {}

  std::ostream& stream() { return file_.stream(); }
  /// Where the writer writes: the temporary file, or the target itself when it is not a regular file.
  const std::string& temp_path() const { return file_.write_path(); }
  void commit() { file_.commit(); }  ///< \throw IoError

 private:
  OutputFile file_;
};

}  // namespace emit
