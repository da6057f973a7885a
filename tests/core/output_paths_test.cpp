// Outputs checked before a job starts (core/output_paths.hpp): an output that is an input, through
// a symlink or a hard link, two outputs that are one file, a folder that is missing or read-only.
#include "emit/core/output_paths.hpp"

#include <sys/stat.h>
#include <sys/sysmacros.h>
#include <sys/wait.h>
#include <unistd.h>
#include <filesystem>
#include <fstream>

#include <gtest/gtest.h>

#include "emit/core/errors.hpp"
#include "test_support.hpp"

namespace emit {
namespace {

namespace fs = std::filesystem;

std::string error_of(const std::vector<NamedPath>& inputs, const std::vector<NamedPath>& outputs) {
  try {
    check_outputs(inputs, outputs);
  } catch (const Error& e) {
    return e.what();
  }
  return "no error";
}

TEST(OutputPaths, AnOutputThatIsAnInputByAnyNameIsRefused) {
  const std::string dir = test::temp_folder("output_paths");
  std::ofstream(dir + "/frames.csv") << "1\n";
  fs::create_symlink(dir + "/frames.csv", dir + "/link.csv");
  fs::create_hard_link(dir + "/frames.csv", dir + "/hard.csv");
  const std::string refused = ": writing it would destroy the input";
  for (const std::string& name : {dir + "/frames.csv", dir + "/./frames.csv", dir + "/link.csv", dir + "/hard.csv"})
    EXPECT_EQ(error_of({{"--frames", dir + "/frames.csv"}}, {{"--contacts", name}}),
              "--contacts " + name + " is the same file as --frames " + dir + "/frames.csv" + refused);
  EXPECT_EQ(error_of({{"--frames", dir + "/frames.csv"}}, {{"--contacts", dir + "/contacts.jsonl"}}), "no error");
  EXPECT_EQ(test::read_text(dir + "/frames.csv"), "1\n");
}

TEST(OutputPaths, TwoOutputsThatAreOneFileAreRefusedEvenBeforeTheyExist) {
  const std::string dir = test::temp_folder("output_paths_two");
  EXPECT_EQ(error_of({}, {{"--out", dir + "/cc.csv"},
                          {"--truth", dir + "/../" + fs::path(dir).filename().string() + "/cc.csv"}}),
            "--out and --truth are the same file (" + dir + "/../" + fs::path(dir).filename().string() + "/cc.csv)");
}

TEST(OutputPaths, AMissingOrReadOnlyFolderOrAFolderAsTheFileIsAnIoError) {
  const std::string dir = test::temp_folder("output_paths_folder");
  EXPECT_EQ(error_of({}, {{"--out", dir + "/no/such/c.json"}}),
            "--out " + dir + "/no/such/c.json: cannot write: folder " + dir + "/no/such does not exist");
  EXPECT_EQ(error_of({}, {{"--out", dir}}), "--out " + dir + ": cannot write: it is a folder");
  if (::geteuid() != 0) {  // root writes anywhere
    fs::create_directory(dir + "/ro");
    fs::permissions(dir + "/ro", fs::perms::owner_read | fs::perms::owner_exec);
    EXPECT_EQ(error_of({}, {{"--out", dir + "/ro/c.json"}})
                  .rfind("--out " + dir + "/ro/c.json: cannot write in folder", 0),
              0u);
    fs::permissions(dir + "/ro", fs::perms::owner_all);
  }
}

// A device or FIFO is written into, not replaced: what matters is whether it is writable, not its
// folder (a user cannot write in /dev, yet may write /dev/null). Several outputs may go into one
// character device, and one that is also an input is no copy of it. Checked as a user other than
// root (root may write anywhere), in a child process.
TEST(OutputPaths, ADeviceIsCheckedForItselfNotForItsFolder) {
  if (::geteuid() != 0) GTEST_SKIP() << "mknod and a change of user need root";
  const std::string dir = test::temp_folder("output_paths_device");
  const std::string null = dir + "/null";
  ASSERT_EQ(::mknod(null.c_str(), S_IFCHR | 0666, makedev(1, 3)), 0);
  ASSERT_EQ(::chmod(null.c_str(), 0666), 0);  // past the umask: anyone may write it, as /dev/null
  ASSERT_EQ(::mknod((dir + "/private").c_str(), S_IFCHR | 0600, makedev(1, 3)), 0);
  EXPECT_EQ(error_of({{"--frames", null}}, {{"--out", null}, {"--truth", null}}), "no error");
  fs::permissions(dir, fs::perms::owner_all | fs::perms::group_read | fs::perms::group_exec | fs::perms::others_read |
                           fs::perms::others_exec);
  int ends[2];
  ASSERT_EQ(::pipe(ends), 0);
  const pid_t child = ::fork();
  ASSERT_GE(child, 0);
  if (child == 0) {
    ::close(ends[0]);
    std::string report = "setuid failed";
    if (::setgid(65534) == 0 && ::setuid(65534) == 0)
      report = error_of({}, {{"--out", null}}) + "\n" + error_of({}, {{"--out", dir + "/private"}}) + "\n" +
               error_of({}, {{"--out", dir + "/c.json"}});
    [[maybe_unused]] const ssize_t written = ::write(ends[1], report.data(), report.size());
    ::_exit(0);
  }
  ::close(ends[1]);
  std::string report;
  char bytes[1024];
  for (ssize_t n; (n = ::read(ends[0], bytes, sizeof bytes)) > 0;) report.append(bytes, static_cast<std::size_t>(n));
  ::close(ends[0]);
  int status = 0;
  ASSERT_EQ(::waitpid(child, &status, 0), child);
  EXPECT_EQ(report, "no error\n--out " + dir + "/private: cannot write (Permission denied)\n--out " + dir +
                        "/c.json: cannot write in folder " + dir + " (Permission denied)");
}

TEST(OutputPaths, AnOutputFolderIsCreatedOrItsProblemNamed) {
  const std::string dir = test::temp_folder("output_paths_images");
  prepare_output_folder({"--images", dir + "/a/b"});
  EXPECT_TRUE(fs::is_directory(dir + "/a/b"));
  std::ofstream(dir + "/file") << "x";
  try {
    prepare_output_folder({"--images", dir + "/file/sub"});
    FAIL() << "no error";
  } catch (const IoError& e) {
    EXPECT_EQ(std::string(e.what()).rfind("--images " + dir + "/file/sub: cannot create the folder (", 0), 0u)
        << e.what();
  }
}

}  // namespace
}  // namespace emit
