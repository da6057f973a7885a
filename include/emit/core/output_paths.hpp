#pragma once
/// \file output_paths.hpp
/// A job's outputs, checked before it reads, builds or writes anything: each can be written (its
/// folder exists and is writable, it is not a folder), none is one of the job's inputs, and no two
/// are one file. "The same file" is the same device and inode, through symlinks and hard links,
/// not the same string.
///
/// Example:
///
///     check_outputs({{"--frames", job.frames_path}}, {{"--contacts", job.contacts_path}});
#include <string>
#include <vector>

namespace emit {

/// A path and the name the user gave it by (the command-line option, e.g. "--contacts").
struct NamedPath {
  std::string name;
  std::string path;  ///< empty: not given, skipped
};

/// \throw InvalidInput "--contacts f.csv is the same file as --frames f.csv: writing it would
///   destroy the input" or "--out and --truth are the same file (f.csv)";
///   IoError "--out d/f.csv: folder d does not exist" / "is not writable" / "is a folder".
void check_outputs(const std::vector<NamedPath>& inputs, const std::vector<NamedPath>& outputs);

/// An output folder (e.g. --images), created if missing. \throw IoError naming it and why.
void prepare_output_folder(const NamedPath& folder);

}  // namespace emit
