#pragma once
/// \file fuzz_support.hpp
/// What the file parsers' fuzz targets share: the input as a file (the parsers take a path), and
/// the property they check: a parser returns, or throws one of emit's own errors (core/errors.hpp).
/// Any other exception is reported with its type and message, then aborts, so libFuzzer keeps the
/// input; crashes, sanitizer reports, hangs (-timeout) and memory (-rss_limit_mb) it catches itself.
#include <unistd.h>

#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <filesystem>
#include <string>
#include <typeinfo>

#include "emit/core/errors.hpp"

namespace emit::fuzz {

/// `size` bytes written to this process's temporary file (created on the first call with
/// `suffix`, rewritten each call, removed at exit); its path.
inline const std::string& input_file(const std::uint8_t* data, std::size_t size, const char* suffix) {
  static const std::string path =
      (std::filesystem::temp_directory_path() / ("emit_fuzz_" + std::to_string(::getpid()) + suffix)).string();
  static const int removed_at_exit = std::atexit([] { std::remove(path.c_str()); });
  (void)removed_at_exit;
  std::FILE* file = std::fopen(path.c_str(), "wb");
  if (file == nullptr || (size > 0 && std::fwrite(data, 1, size, file) != size) || std::fclose(file) != 0) {
    std::perror(path.c_str());
    std::abort();
  }
  return path;
}

/// Runs parse(): returning or throwing an emit::Error is fine; any other exception is a finding.
template <class Parse>
void expect_only_emit_errors(Parse&& parse) {
  try {
    parse();
  } catch (const emit::Error&) {
    // the parser rejected the input, as it should
  } catch (const std::exception& e) {
    std::fprintf(stderr, "fuzz: not an emit::Error: %s: %s\n", typeid(e).name(), e.what());
    std::abort();
  } catch (...) {
    std::fprintf(stderr, "fuzz: not an emit::Error: an exception not derived from std::exception\n");
    std::abort();
  }
}

}  // namespace emit::fuzz
