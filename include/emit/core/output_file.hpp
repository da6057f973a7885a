#pragma once
/// \file output_file.hpp
/// The one rule every output of emit follows (each command's files, Python's Calibration.save):
///
///  - a regular file, or a name where nothing is yet: written to a temporary file beside it and
///    renamed over it by commit(), so an error half-way never leaves a half file over a good one
///    (through a symlink, the file it points to is replaced, not the link);
///  - anything else that is there (a character or block device such as /dev/null, a FIFO, a
///    terminal) and a descriptor's name (/dev/stdout, /dev/stderr, /dev/fd/N, /proc/self/fd/N):
///    written into directly, as `cat > PATH` would, with no temporary file and no rename: it is
///    never replaced; commit() flushes it and reports a failed write;
///  - "-", where the option allows it: standard output, directly.
///
/// Every error names the output as the user gave it, option and path: "--out r/full: write
/// failed (No space left on device)". A job opens all its outputs at once, before it reads any
/// input (core/output_paths.hpp's open_outputs): if one cannot be opened, the others are closed
/// and their temporary files removed, so nothing is touched.
///
/// Example:
///
///     emit::OutputFile out({"--out", path});
///     out.stream() << text;
///     out.commit();   // renamed over `path`, or flushed into a device
#include <cstdint>
#include <memory>
#include <ostream>
#include <string>

namespace emit {

/// A path and the name the user gave it by (the command-line option, e.g. "--contacts").
struct NamedPath {
  std::string name;  ///< empty: messages name the path alone
  std::string path;  ///< empty: not given, skipped
};

/// What an output's path is, and so how it is written (see the file's comment).
enum class OutputKind {
  file,        ///< a regular file or nothing yet: a temporary file, renamed on commit
  device,      ///< a character or block device (or a socket): written directly
  fifo,        ///< a named pipe: written directly; a new reader may come when one leaves
  descriptor,  ///< standard output ("-") or a descriptor's name (/dev/stdout, /dev/fd/N): written directly
  folder,      ///< a folder: cannot be written (OutputFile refuses it)
};

/// The kind of `path` as it is now (symlinks followed). `standard_output`: "-" is standard output.
OutputKind output_kind(const std::string& path, bool standard_output = false);
/// The file a regular output replaces: `path`, or through a symlink the file it points to.
std::string replaced_file(const std::string& path);

struct OutputOptions {
  /// A regular file's temporary file: hidden (".NAME.tmpPID.EXT", the extension kept for writers
  /// that choose their format by it), removed when the output is abandoned: a result is whole or
  /// absent. Or `partial`: "PATH.partial", a recording's, kept as it got once anything was written
  /// into it (after an error or a crash, every frame it holds is worth keeping; PATH is untouched).
  bool partial = false;
  bool standard_output = false;  ///< "-" is standard output (otherwise a file named "-")
  /// false: the writer opens write_path() itself (libpng, Gmsh); no stream is opened.
  bool stream = true;
};

class OutputFile {
 public:
  OutputFile();  ///< no output: given() is false
  /// Opens the output: creates the temporary file, or opens the device, FIFO (waiting for its
  /// reader, as any writer of a FIFO does) or descriptor.
  /// \throw IoError naming it: "--out d/f.csv: cannot write: folder d does not exist", "…: it is
  ///   a folder", "--mcap x.mcap: cannot create x.mcap.partial (Is a directory)", "…: cannot write
  ///   (Permission denied)".
  explicit OutputFile(NamedPath target, OutputOptions options = {});
  /// Unless committed: a temporary file is removed (a partial one that was written into stays); a
  /// direct output is closed, what its buffer held dropped.
  ~OutputFile();
  OutputFile(OutputFile&&) noexcept;
  OutputFile& operator=(OutputFile&&) noexcept;
  OutputFile(const OutputFile&) = delete;
  OutputFile& operator=(const OutputFile&) = delete;

  bool given() const { return state_ != nullptr; }
  OutputKind kind() const;
  bool direct() const { return kind() != OutputKind::file; }
  const std::string& path() const;  ///< as given
  std::string describe() const;     ///< "--out r/full", or the path alone when unnamed
  /// Where the bytes go: the temporary file, or the target itself when written directly (for a
  /// writer that opens it, OutputOptions::stream = false).
  const std::string& write_path() const;

  /// Buffered; a failed write sets the stream's badbit (check() says why).
  std::ostream& stream();
  /// \throw IoError if a write has failed: "--contacts -: write failed (Broken pipe)".
  void check() const;
  /// The last write failed because no one reads the pipe or FIFO any more (EPIPE).
  bool reader_gone() const;
  /// A write interrupted by a signal whose handler does not restart it (`emit live`'s stop, while
  /// a reader did not read): what was buffered is dropped and the stream cleared, to go on or
  /// finish. \return whether the last write was interrupted.
  bool clear_interrupted();
  /// A named FIFO whose reader went away: true once a new reader has opened it (without waiting:
  /// false while none has), the stream cleared and empty. Allocates nothing.
  bool reconnect();

  /// Flushes and closes. \throw IoError if a write failed. Later calls do nothing.
  void finish();
  /// finish(), then renames the temporary file over the target (nothing more for a direct
  /// output). \throw IoError. Later calls do nothing.
  void commit();

 private:
  struct State;
  std::unique_ptr<State> state_;
};

/// SIGINT, SIGTERM and SIGHUP remove every OutputFile's temporary file (a partial one only while
/// nothing was written into it), then end the process as the signal would have (the default
/// action, re-raised). Handlers installed later (e.g. `emit live`'s graceful stop) take
/// precedence while they are installed.
void remove_temporary_files_on_signals();

}  // namespace emit
