// Write-then-rename (core/atomic_file.hpp): the target changes only on commit, the temporary file
// keeps the target's extension and goes away either way.
#include "emit/core/atomic_file.hpp"

#include <filesystem>
#include <fstream>

#include <gtest/gtest.h>

#include "emit/core/errors.hpp"
#include "test_support.hpp"

namespace emit {
namespace {

namespace fs = std::filesystem;

TEST(AtomicFile, TargetChangesOnlyOnCommit) {
  const std::string dir = test::temp_folder("atomic_commit");
  const std::string path = dir + "/out.csv";
  std::ofstream(path) << "old\n";
  {
    AtomicFile file(path);
    EXPECT_EQ(fs::path(file.temp_path()).parent_path(), fs::path(dir));
    EXPECT_EQ(fs::path(file.temp_path()).extension(), ".csv");
    file.stream() << "new\n";
    EXPECT_EQ(test::read_text(path), "old\n");
    file.commit();
    EXPECT_FALSE(fs::exists(file.temp_path()));
  }
  EXPECT_EQ(test::read_text(path), "new\n");
}

TEST(AtomicFile, AbandonedFileLeavesTheTargetAndNoTemporary) {
  const std::string dir = test::temp_folder("atomic_abandon");
  const std::string path = dir + "/out.json";
  std::ofstream(path) << "old\n";
  std::string temp;
  {
    AtomicFile file(path);
    temp = file.temp_path();
    file.stream() << "half";
    EXPECT_TRUE(fs::exists(temp));
  }
  EXPECT_FALSE(fs::exists(temp));
  EXPECT_EQ(test::read_text(path), "old\n");
}

// Without a stream (a writer such as Gmsh writes the temporary path itself), commit renames
// whatever is there; with nothing there, it says it cannot replace the file.
TEST(AtomicFile, WithoutAStreamCommitRenamesWhatTheWriterWrote) {
  const std::string dir = test::temp_folder("atomic_no_stream");
  const std::string path = dir + "/sheet.msh";
  {
    AtomicFile file(path, false);
    std::ofstream(file.temp_path()) << "mesh\n";
    file.commit();
  }
  EXPECT_EQ(test::read_text(path), "mesh\n");
  AtomicFile nothing(dir + "/none.msh", false);
  try {
    nothing.commit();
    FAIL() << "no error";
  } catch (const IoError& e) {
    EXPECT_EQ(std::string(e.what()), dir + "/none.msh: cannot replace file (No such file or directory)");
  }
}

TEST(AtomicFile, MissingFolderIsAnErrorNamingIt) {
  const std::string dir = test::temp_folder("atomic_folder");
  try {
    AtomicFile file(dir + "/no/out.csv");
    FAIL() << "no error";
  } catch (const IoError& e) {
    EXPECT_EQ(std::string(e.what()), dir + "/no/out.csv: cannot write: folder " + dir + "/no does not exist");
  }
}

}  // namespace
}  // namespace emit
