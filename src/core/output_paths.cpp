#include "emit/core/output_paths.hpp"

#include <sys/stat.h>
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

/// Writing a character device (/dev/null, a terminal) destroys nothing read from it, and several
/// outputs may go into one.
bool character_device(const std::string& path) {
  struct stat status {};
  return ::stat(path.c_str(), &status) == 0 && S_ISCHR(status.st_mode);
}

void check_writable(const NamedPath& output) {
  const std::string what = output.name + " " + output.path;
  switch (output_kind(output.path)) {
    case OutputKind::folder: throw IoError(what + ": cannot write: it is a folder");
    case OutputKind::file: {  // a temporary file beside it, renamed over it
      const fs::path path(replaced_file(output.path));
      const fs::path folder = path.parent_path().empty() ? fs::path(".") : path.parent_path();
      std::error_code error;
      if (!fs::is_directory(folder, error))
        throw IoError(what + ": cannot write: folder " + folder.string() + " does not exist");
      if (::access(folder.c_str(), W_OK) != 0)
        throw IoError(what + ": cannot write in folder " + folder.string() + " (" + std::strerror(errno) + ")");
      return;
    }
    default:  // written into directly: its folder does not matter
      if (::access(output.path.c_str(), W_OK) != 0)
        throw IoError(what + ": cannot write (" + std::strerror(errno) + ")");
  }
}

}  // namespace

void check_outputs(const std::vector<NamedPath>& inputs, const std::vector<NamedPath>& outputs) {
  for (std::size_t o = 0; o < outputs.size(); ++o) {
    const NamedPath& output = outputs[o];
    if (output.path.empty()) continue;
    check_writable(output);
    if (character_device(output.path)) continue;
    for (const NamedPath& input : inputs)
      if (!input.path.empty() && same_file(output.path, input.path))
        throw InvalidInput(output.name + " " + output.path + " is the same file as " + input.name + " " + input.path +
                           ": writing it would destroy the input");
    for (std::size_t other = 0; other < o; ++other)
      if (!outputs[other].path.empty() && same_file(output.path, outputs[other].path))
        throw InvalidInput(outputs[other].name + " and " + output.name + " are the same file (" + output.path + ")");
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

void open_outputs(const std::vector<NamedPath>& inputs, std::span<const OutputRequest> requests,
                  std::span<OutputFile> files) {
  std::vector<NamedPath> checked;
  for (const OutputRequest& request : requests) {
    const bool standard_output = request.options.standard_output && request.target.path == "-";
    checked.push_back({request.target.name, standard_output ? "" : request.target.path});
  }
  check_outputs(inputs, checked);
  // FIFOs last: opening one waits for its reader, and an output that cannot be opened should be
  // refused before that wait.
  for (const bool fifos : {false, true})
    for (std::size_t i = 0; i < requests.size(); ++i) {
      const OutputRequest& request = requests[i];
      if (request.target.path.empty()) continue;
      if ((output_kind(request.target.path, request.options.standard_output) == OutputKind::fifo) != fifos) continue;
      files[i] = OutputFile(request.target, request.options);
    }
}

void commit_outputs(std::span<OutputFile> files) {
  for (OutputFile& file : files)
    if (file.given()) file.finish();
  for (OutputFile& file : files)
    if (file.given()) file.commit();
}

}  // namespace emit
