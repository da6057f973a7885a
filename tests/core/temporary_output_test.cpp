// Write-then-rename, a regular file's output (core/output_file.hpp): the target changes only on commit, the temporary
// file keeps the target's extension and goes away either way.
#include "emit/core/output_file.hpp"

#include <sys/wait.h>
#include <unistd.h>

#include <csignal>
#include <filesystem>
#include <fstream>

#include <gtest/gtest.h>

#include "emit/core/errors.hpp"
#include "test_support.hpp"

namespace emit {
namespace {

namespace fs = std::filesystem;

TEST(TemporaryOutput, TargetChangesOnlyOnCommit) {
  const std::string dir = test::temp_folder("atomic_commit");
  const std::string path = dir + "/out.csv";
  std::ofstream(path) << "old\n";
  {
    OutputFile file({"", path});
    EXPECT_EQ(fs::path(file.write_path()).parent_path(), fs::path(dir));
    EXPECT_EQ(fs::path(file.write_path()).extension(), ".csv");
    file.stream() << "new\n";
    EXPECT_EQ(test::read_text(path), "old\n");
    file.commit();
    EXPECT_FALSE(fs::exists(file.write_path()));
  }
  EXPECT_EQ(test::read_text(path), "new\n");
}

TEST(TemporaryOutput, AbandonedFileLeavesTheTargetAndNoTemporary) {
  const std::string dir = test::temp_folder("atomic_abandon");
  const std::string path = dir + "/out.json";
  std::ofstream(path) << "old\n";
  std::string temp;
  {
    OutputFile file({"", path});
    temp = file.write_path();
    file.stream() << "half";
    EXPECT_TRUE(fs::exists(temp));
  }
  EXPECT_FALSE(fs::exists(temp));
  EXPECT_EQ(test::read_text(path), "old\n");
}

// Without a stream (a writer such as Gmsh writes the temporary path itself), commit renames
// whatever is there; with nothing there, it says it cannot replace the file.
TEST(TemporaryOutput, WithoutAStreamCommitRenamesWhatTheWriterWrote) {
  const std::string dir = test::temp_folder("atomic_no_stream");
  const std::string path = dir + "/sheet.msh";
  {
    OutputFile file({"", path}, {.stream = false});
    std::ofstream(file.write_path()) << "mesh\n";
    file.commit();
  }
  EXPECT_EQ(test::read_text(path), "mesh\n");
  OutputFile nothing({"", dir + "/none.msh"}, {.stream = false});
  try {
    nothing.commit();
    FAIL() << "no error";
  } catch (const IoError& e) {
    EXPECT_EQ(std::string(e.what()), dir + "/none.msh: cannot replace file (No such file or directory)");
  }
}

TEST(TemporaryOutput, MissingFolderIsAnErrorNamingIt) {
  const std::string dir = test::temp_folder("atomic_folder");
  try {
    OutputFile file({"", dir + "/no/out.csv"});
    FAIL() << "no error";
  } catch (const IoError& e) {
    EXPECT_EQ(std::string(e.what()), dir + "/no/out.csv: cannot write: folder " + dir + "/no does not exist");
  }
}

}  // namespace
}  // namespace emit

namespace emit {
namespace {

// Ctrl-C during `emit reconstruct` used to leave a hidden ".NAME.tmpPID.jsonl" behind. A child
// process opens an OutputFile, writes, and is killed by SIGINT with the cleanup installed: the
// temporary file is gone, the target untouched, and the child died of the signal (re-raised).
TEST(TemporaryOutput, ASignalRemovesTheTemporaryFileAndStillEndsTheProcess) {
  const std::string dir = test::temp_folder("atomic_file_signal");
  const std::string target = dir + "/contacts.jsonl";
  std::ofstream(target) << "GOOD\n";
  const pid_t child = ::fork();
  ASSERT_GE(child, 0);
  if (child == 0) {
    remove_temporary_files_on_signals();
    OutputFile file({"", target});
    file.stream() << "half" << std::flush;
    std::raise(SIGINT);
    ::_exit(0);  // not reached: SIGINT's default action ends the process
  }
  int status = 0;
  ASSERT_EQ(::waitpid(child, &status, 0), child);
  ASSERT_TRUE(WIFSIGNALED(status));
  EXPECT_EQ(WTERMSIG(status), SIGINT);
  EXPECT_EQ(test::read_text(target), "GOOD\n");
  std::size_t files = 0;
  for ([[maybe_unused]] const auto& entry : std::filesystem::directory_iterator(dir)) ++files;
  EXPECT_EQ(files, 1u) << "a temporary file was left in " << dir;
}

}  // namespace
}  // namespace emit
