#include "sheet_file_access.hpp"

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <system_error>

#include "emit/core/errors.hpp"
#include "emit/core/quote_input.hpp"

namespace emit::detail {

void check_sheet_file_access(const std::string& path, const std::string& kind) {
  const std::string file = quote_input(path, 120);
  std::error_code error;
  const auto status = std::filesystem::status(path, error);
  // The file system's own verdict (a name or a part of it beyond NAME_MAX or PATH_MAX): the
  // standard library throws it without a word of where, so it is said here.
  if (error == std::errc::filename_too_long)
    throw InvalidInput(quote_input(path, 40) + ": the " + kind + "'s name is too long for the file system (" +
                       std::to_string(path.size()) + " characters; at most 255 between slashes, 4095 in all)");
  if (error && error != std::errc::no_such_file_or_directory && error != std::errc::not_a_directory)
    throw IoError(file + ": cannot read " + kind + " (" + error.message() + ")");
  if (!std::filesystem::exists(status)) throw IoError(file + ": no such " + kind);
  if (!std::filesystem::is_regular_file(status)) throw IoError(file + ": the " + kind + " is not a regular file");
  if (!std::ifstream(path, std::ios::binary))
    throw IoError(file + ": cannot read " + kind + " (" + std::strerror(errno) + ")");
}

}  // namespace emit::detail
