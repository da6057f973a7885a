// The one output rule (core/output_file.hpp, core/output_paths.hpp's open_outputs): a regular file
// through a temporary file renamed over it; a device, FIFO or descriptor written into directly,
// never replaced, its write errors named; all of a job's outputs opened before any is touched.
// Devices are private nodes made with mknod in a temporary folder (root only), never the
// machine's own /dev/null or /dev/full.
#include "emit/core/output_file.hpp"

#include <fcntl.h>
#include <sys/stat.h>
#include <sys/sysmacros.h>
#include <sys/wait.h>
#include <unistd.h>

#include <csignal>
#include <filesystem>
#include <fstream>
#include <set>

#include <gtest/gtest.h>

#include "emit/core/errors.hpp"
#include "emit/core/output_paths.hpp"
#include "test_support.hpp"

namespace emit {
namespace {

namespace fs = std::filesystem;

std::set<std::string> names_in(const std::string& folder) {
  std::set<std::string> names;
  for (const auto& entry : fs::directory_iterator(folder)) names.insert(entry.path().filename().string());
  return names;
}

bool is_character_device(const std::string& path) {
  struct stat status {};
  return ::lstat(path.c_str(), &status) == 0 && S_ISCHR(status.st_mode);
}

/// A private copy of a memory device: 3 is /dev/null's minor number, 7 /dev/full's.
std::string make_memory_device(const std::string& folder, const std::string& name, unsigned minor) {
  std::string path = folder + "/" + name;
  if (::mknod(path.c_str(), S_IFCHR | 0666, makedev(1, minor)) != 0) return "";
  return path;
}

std::string read_available(int fd) {
  char bytes[4096];
  const ssize_t n = ::read(fd, bytes, sizeof bytes);
  return n > 0 ? std::string(bytes, static_cast<std::size_t>(n)) : "";
}

// Outputs that are devices were replaced by regular files (as root, `--contacts /dev/null` made
// /dev/null a file) and a write to a full device "succeeded".
TEST(OutputFile, ADeviceIsWrittenIntoNeverReplacedAndItsErrorsNamed) {
  if (::geteuid() != 0) GTEST_SKIP() << "mknod needs root";
  const std::string dir = test::temp_folder("output_file_device");
  const std::string null = make_memory_device(dir, "null", 3), full = make_memory_device(dir, "full", 7);
  ASSERT_FALSE(null.empty() || full.empty()) << "mknod failed";
  {
    OutputFile out({"--out", null});
    EXPECT_EQ(out.kind(), OutputKind::device);
    EXPECT_EQ(out.write_path(), null);  // no temporary file
    out.stream() << std::string(200'000, 'x');
    out.commit();
  }
  EXPECT_TRUE(is_character_device(null));
  OutputFile out({"--out", full});
  out.stream() << "1,2,3\n";
  EXPECT_EQ(test::error_of([&] { out.commit(); }), "--out " + full + ": write failed (No space left on device)");
  EXPECT_TRUE(is_character_device(full));
  EXPECT_EQ(names_in(dir), (std::set<std::string>{"full", "null"}));
}

// A descriptor's name (/dev/fd/N, /proc/self/fd/N, /dev/stdout) is written through the descriptor,
// and "-" is standard output only where the option allows it.
TEST(OutputFile, ADescriptorsNameIsWrittenThroughIt) {
  int ends[2];
  ASSERT_EQ(::pipe(ends), 0);
  for (const std::string& name : {"/dev/fd/" + std::to_string(ends[1]), "/proc/self/fd/" + std::to_string(ends[1])}) {
    OutputFile out({"--contacts", name});
    EXPECT_EQ(out.kind(), OutputKind::descriptor) << name;
    out.stream() << "line\n";
    out.commit();
    EXPECT_EQ(read_available(ends[0]), "line\n") << name;
  }
  ::close(ends[0]);
  ::close(ends[1]);
  EXPECT_EQ(output_kind("/dev/stdout"), OutputKind::descriptor);
  EXPECT_EQ(output_kind("-", /*standard_output=*/true), OutputKind::descriptor);
  EXPECT_EQ(output_kind("-"), OutputKind::file);  // a file named "-"
}

// Through a symlink, the file it points to is replaced and the link stays a link.
TEST(OutputFile, ThroughASymlinkTheFileItPointsToIsReplaced) {
  const std::string dir = test::temp_folder("output_file_symlink");
  fs::create_directory(dir + "/data");
  std::ofstream(dir + "/data/real.csv") << "old\n";
  fs::create_symlink("data/real.csv", dir + "/link.csv");
  OutputFile out({"--out", dir + "/link.csv"});
  out.stream() << "new\n";
  out.commit();
  EXPECT_TRUE(fs::is_symlink(dir + "/link.csv"));
  EXPECT_EQ(test::read_text(dir + "/data/real.csv"), "new\n");
  EXPECT_EQ(names_in(dir + "/data"), (std::set<std::string>{"real.csv"}));
}

// A recording's PATH.partial stays when abandoned once it holds something (its frames are worth
// keeping), and goes when it is empty (a run that failed before its first byte).
TEST(OutputFile, APartialFileStaysOnceWrittenIntoAndGoesWhileEmpty) {
  const std::string dir = test::temp_folder("output_file_partial");
  std::ofstream(dir + "/run.mcap") << "good\n";
  { OutputFile empty({"--mcap", dir + "/run.mcap"}, {.partial = true}); }
  EXPECT_EQ(names_in(dir), (std::set<std::string>{"run.mcap"}));
  {
    OutputFile written({"--mcap", dir + "/run.mcap"}, {.partial = true});
    EXPECT_EQ(written.write_path(), dir + "/run.mcap.partial");
    written.stream() << "frames";
  }
  EXPECT_EQ(test::read_text(dir + "/run.mcap.partial"), "frames");
  EXPECT_EQ(test::read_text(dir + "/run.mcap"), "good\n");
}

// A FIFO whose reader goes away (EPIPE, SIGPIPE ignored) reports it; reconnect() waits for no one
// and takes the next reader, who gets whole lines from then on.
TEST(OutputFile, AFifosReaderMayLeaveAndANewOneTakeOver) {
  const std::string dir = test::temp_folder("output_file_fifo");
  const std::string fifo = dir + "/contacts.fifo";
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
  const auto old_pipe_handler = std::signal(SIGPIPE, SIG_IGN);
  int reader = ::open(fifo.c_str(), O_RDONLY | O_NONBLOCK);  // there first: opening the writer waits for none
  ASSERT_GE(reader, 0);
  OutputFile out({"--contacts", fifo});
  EXPECT_EQ(out.kind(), OutputKind::fifo);
  out.stream() << "frame 1\n" << std::flush;
  EXPECT_EQ(read_available(reader), "frame 1\n");
  ::close(reader);
  out.stream() << "frame 2\n" << std::flush;
  EXPECT_FALSE(out.stream());
  EXPECT_TRUE(out.reader_gone());
  EXPECT_EQ(test::error_of([&] { out.check(); }), "--contacts " + fifo + ": write failed (Broken pipe)");
  EXPECT_FALSE(out.reconnect());  // no reader yet
  reader = ::open(fifo.c_str(), O_RDONLY | O_NONBLOCK);
  ASSERT_GE(reader, 0);
  EXPECT_TRUE(out.reconnect());
  EXPECT_FALSE(out.reader_gone());
  out.stream() << "frame 3\n" << std::flush;
  EXPECT_TRUE(out.stream());
  EXPECT_EQ(read_available(reader), "frame 3\n");  // frame 2 was dropped whole, not half-delivered
  out.commit();
  ::close(reader);
  std::signal(SIGPIPE, old_pipe_handler);
}

// Finding: `emit live` truncated its --contacts file, then failed to open --mcap. Every output
// is opened first; one that cannot be opened leaves the others as they were, with no temporary.
TEST(OpenOutputs, OneThatCannotBeOpenedTouchesNone) {
  const std::string dir = test::temp_folder("open_outputs");
  std::ofstream(dir + "/c.jsonl") << "GOOD\n";
  std::ofstream(dir + "/rec.emitrec") << "OLD";
  fs::create_directory(dir + "/x.mcap.partial");  // left by someone
  const std::string message = test::error_of([&] {
    open_outputs({}, {OutputRequest{{"--contacts", dir + "/c.jsonl"}, {.partial = true}},
                      OutputRequest{{"--record", dir + "/rec.emitrec"}, {.partial = true}},
                      OutputRequest{{"--mcap", dir + "/x.mcap"}, {.partial = true}}});
  });
  EXPECT_EQ(message, "--mcap " + dir + "/x.mcap: cannot create " + dir + "/x.mcap.partial (Is a directory)");
  EXPECT_EQ(test::read_text(dir + "/c.jsonl"), "GOOD\n");
  EXPECT_EQ(test::read_text(dir + "/rec.emitrec"), "OLD");
  EXPECT_EQ(names_in(dir), (std::set<std::string>{"c.jsonl", "rec.emitrec", "x.mcap.partial"}));
  const std::string long_name = dir + "/" + std::string(250, 'y') + ".mcap";  // too long once ".partial" is added
  EXPECT_NE(test::error_of([&] {
              open_outputs({}, {OutputRequest{{"--contacts", dir + "/c.jsonl"}},
                                OutputRequest{{"--mcap", long_name}, {.partial = true}}});
            }).find(".partial (File name too long)"),
            std::string::npos);
  EXPECT_EQ(names_in(dir), (std::set<std::string>{"c.jsonl", "rec.emitrec", "x.mcap.partial"}));
}

// Outputs are finished (flushed) before any is renamed: a failed write leaves every target as it was.
TEST(OpenOutputs, AFailedWriteRenamesNoOutput) {
  if (::geteuid() != 0) GTEST_SKIP() << "mknod needs root";
  const std::string dir = test::temp_folder("open_outputs_commit");
  const std::string full = make_memory_device(dir, "full", 7);
  ASSERT_FALSE(full.empty());
  std::ofstream(dir + "/truth.csv") << "old\n";
  auto outputs = open_outputs({}, {OutputRequest{{"--truth", dir + "/truth.csv"}}, OutputRequest{{"--out", full}}});
  outputs[0].stream() << "new\n";
  outputs[1].stream() << "frames\n";
  EXPECT_EQ(test::error_of([&] { commit_outputs(outputs); }),
            "--out " + full + ": write failed (No space left on device)");
  EXPECT_EQ(test::read_text(dir + "/truth.csv"), "old\n");
}

// A signal removes the temporary files, and a partial one only while it is empty.
TEST(OutputFile, ASignalKeepsAPartialFileThatHoldsSomething) {
  const std::string dir = test::temp_folder("output_file_signal");
  const pid_t child = ::fork();
  ASSERT_GE(child, 0);
  if (child == 0) {
    remove_temporary_files_on_signals();
    OutputFile hidden({"", dir + "/contacts.jsonl"});
    OutputFile empty({"", dir + "/empty.mcap"}, {.partial = true});
    OutputFile recording({"", dir + "/run.emitrec"}, {.partial = true});
    recording.stream() << "frames" << std::flush;
    std::raise(SIGTERM);
    ::_exit(0);  // not reached
  }
  int status = 0;
  ASSERT_EQ(::waitpid(child, &status, 0), child);
  ASSERT_TRUE(WIFSIGNALED(status));
  EXPECT_EQ(WTERMSIG(status), SIGTERM);
  EXPECT_EQ(names_in(dir), (std::set<std::string>{"run.emitrec.partial"}));
}

}  // namespace
}  // namespace emit
