#pragma once
/// \file output_paths.hpp
/// A job's outputs, checked and opened before it reads, builds or writes anything: each can be
/// written (its folder exists and is writable, it is not a folder; a device or FIFO is writable
/// itself), none is one of the job's inputs, and no two are one file. "The same file" is the
/// same device and inode, through symlinks and hard links, not the same string; a character
/// device (/dev/null, a terminal) is no input's copy and may take several outputs.
///
/// Example:
///
///     auto outputs = open_outputs({{"--frames", job.frames_path}},
///                                 {OutputRequest{{"--contacts", job.contacts_path}},
///                                  OutputRequest{{"--mcap", job.mcap_path}, {.partial = true}}});
///     auto& [contacts, mcap] = outputs;   // opened, or not given()
#include <array>
#include <cstddef>
#include <span>
#include <string>
#include <vector>

#include "emit/core/output_file.hpp"

namespace emit {

/// \throw InvalidInput "--contacts f.csv is the same file as --frames f.csv: writing it would
///   destroy the input" or "--out and --truth are the same file (f.csv)";
///   IoError "--out d/f.csv: folder d does not exist" / "is not writable" / "is a folder".
void check_outputs(const std::vector<NamedPath>& inputs, const std::vector<NamedPath>& outputs);

/// An output folder (e.g. --images), created if missing. \throw IoError naming it and why.
void prepare_output_folder(const NamedPath& folder);

/// One output of a job: where, and how (core/output_file.hpp). An empty path: not given.
struct OutputRequest {
  NamedPath target;
  OutputOptions options = {};
};

/// check_outputs(), then every output opened (temporary files created, devices opened; FIFOs
/// last, since opening one waits for its reader). If one fails, those opened are closed and their
/// temporary files removed: nothing is touched. `files[i]` is `requests[i]`'s, or not given().
/// \throw as check_outputs() and OutputFile's constructor.
void open_outputs(const std::vector<NamedPath>& inputs, std::span<const OutputRequest> requests,
                  std::span<OutputFile> files);

template <std::size_t N>
std::array<OutputFile, N> open_outputs(const std::vector<NamedPath>& inputs, const OutputRequest (&requests)[N]) {
  std::array<OutputFile, N> files;
  open_outputs(inputs, requests, files);
  return files;
}

/// Every given output finished (flushed, closed: a failed write throws here, before any is
/// renamed), then committed. \throw IoError naming the output.
void commit_outputs(std::span<OutputFile> files);

}  // namespace emit
