#include "emit/core/output_paths.hpp"

#include <unistd.h>
#include <cerrno>
#include <cstring>
#include <filesystem>
#include <system_error>

#include "emit/core/errors.hpp"

namespace emit {

namespace fs = std::filesystem;

namespace {

/// Same device and inode (both exist), or, for paths not created yet, the same absolute path.
bool same_file(const std::string& a, const std::string& b) {
  std::error_code error;
  if (fs::equivalent(a, b, error)) return true;
  const fs::path canonical_a = fs::weakly_canonical(a, error);
  if (error) return false;
  const fs::path canonical_b = fs::weakly_canonical(b, error);
  return !error && canonical_a == canonical_b;
}

void check_writable(const NamedPath& output) {
  const fs::path path(output.path);
  const fs::path folder = path.parent_path().empty() ? fs::path(".") : path.parent_path();
  const std::string what = output.name + " " + output.path;
  std::error_code error;
  if (!fs::is_directory(folder, error))
    throw IoError(what + ": cannot write: folder " + folder.string() + " does not exist");
  if (::access(folder.c_str(), W_OK) != 0)
    throw IoError(what + ": cannot write in folder " + folder.string() + " (" + std::strerror(errno) + ")");
  if (fs::is_directory(path, error)) throw IoError(what + ": cannot write: it is a folder");
}

}  // namespace

void check_outputs(const std::vector<NamedPath>& inputs, const std::vector<NamedPath>& outputs) {
  for (std::size_t o = 0; o < outputs.size(); ++o) {
    const NamedPath& output = outputs[o];
    if (output.path.empty()) continue;
    for (const NamedPath& input : inputs)
      if (!input.path.empty() && same_file(output.path, input.path))
        throw InvalidInput(output.name + " " + output.path + " is the same file as " + input.name + " " + input.path +
                           ": writing it would destroy the input");
    for (std::size_t other = 0; other < o; ++other)
      if (!outputs[other].path.empty() && same_file(output.path, outputs[other].path))
        throw InvalidInput(outputs[other].name + " and " + output.name + " are the same file (" + output.path + ")");
    check_writable(output);
  }
}

void prepare_output_folder(const NamedPath& folder) {
  if (folder.path.empty()) return;
  std::error_code error;
  fs::create_directories(folder.path, error);
  if (error) throw IoError(folder.name + " " + folder.path + ": cannot create the folder (" + error.message() + ")");
  if (::access(folder.path.c_str(), W_OK) != 0)
    throw IoError(folder.name + " " + folder.path + ": cannot write in the folder (" + std::strerror(errno) + ")");
}

}  // namespace emit
