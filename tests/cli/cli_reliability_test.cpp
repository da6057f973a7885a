// End to end, the cases of docs/bad-input.md that need more than one bad command line
// (cli_test.cpp's CliBadInput holds the rest): a signal mid-run, a failing live source, warnings
// that let the run go on, and options after the command.
#include <fcntl.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>
#include <csignal>

#include <chrono>
#include <csignal>
#include <filesystem>
#include <fstream>
#include <thread>
#include <vector>

#include <gtest/gtest.h>

#include "test_support.hpp"

extern char** environ;

namespace emit {
namespace {

namespace fs = std::filesystem;
using test::run_emit;

std::string zero_frames(int count) {
  std::string row;
  for (int i = 0; i < 256; ++i) row += i ? ",0" : "0";
  std::string text;
  for (int f = 0; f < count; ++f) text += row + "\n";
  return text;
}

std::vector<std::string> hidden_files(const std::string& dir) {
  std::vector<std::string> names;
  for (const auto& entry : fs::directory_iterator(dir))
    if (entry.path().filename().string().rfind('.', 0) == 0) names.push_back(entry.path().filename().string());
  return names;
}

// Finding 4: Ctrl-C during `emit reconstruct` kept the good contacts file but left a hidden
// ".contacts.tmpPID.jsonl". Now the temporary file goes, and emit still dies of the signal.
TEST(CliReliability, CtrlCDuringReconstructLeavesNoTemporaryFile) {
  const std::string dir = test::temp_folder("cli_sigint");
  std::ofstream(dir + "/ref.csv") << zero_frames(1);
  std::ofstream(dir + "/frames.csv") << zero_frames(400);
  std::ofstream(dir + "/contacts.jsonl") << "GOOD\n";
  const std::vector<std::string> arguments = {test::cli_path(), "reconstruct",
                                              "--method",       "paper",
                                              "--reference",    dir + "/ref.csv",
                                              "--frames",       dir + "/frames.csv",
                                              "--contacts",     dir + "/contacts.jsonl",
                                              "--images",       dir + "/images",
                                              "--no-cache"};
  std::vector<char*> argv;
  argv.reserve(arguments.size() + 1);
  for (const std::string& a : arguments) argv.push_back(const_cast<char*>(a.c_str()));
  argv.push_back(nullptr);
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_addopen(&actions, 2, (dir + "/stderr").c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
  pid_t child = 0;
  ASSERT_EQ(posix_spawn(&child, argv[0], &actions, nullptr, argv.data(), environ), 0);
  posix_spawn_file_actions_destroy(&actions);
  // Wait for the first pictures: the model is built and the temporary contacts file is half written.
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(60);
  while (!fs::exists(dir + "/images/frame_3.png") && std::chrono::steady_clock::now() < deadline)
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  ASSERT_EQ(hidden_files(dir).size(), 1u) << "the temporary contacts file should exist mid-run";
  ::kill(child, SIGINT);
  int status = 0;
  ASSERT_EQ(::waitpid(child, &status, 0), child);
  ASSERT_TRUE(WIFSIGNALED(status)) << "emit finished before the signal: give it more frames";
  EXPECT_EQ(WTERMSIG(status), SIGINT);
  EXPECT_TRUE(hidden_files(dir).empty()) << hidden_files(dir)[0];
  EXPECT_EQ(test::read_text(dir + "/contacts.jsonl"), "GOOD\n");
}

// Finding 1: a live source that cannot be opened left 0 bytes where a good contacts file was.
TEST(CliReliability, AFailingLiveSourceLeavesTheContactsFile) {
  const std::string dir = test::temp_folder("cli_live_source");
  std::ofstream(dir + "/good.jsonl") << "GOOD\n";
  for (const std::string& source :
       {std::string("bogus:"), "file:" + dir + "/none.emitrec", "serial:" + dir + "/no-tty"}) {
    const auto r = run_emit("live --source " + source + " --contacts " + dir + "/good.jsonl --frames 1");
    EXPECT_EQ(r.exit_code, 1) << r.err;
    EXPECT_EQ(test::read_text(dir + "/good.jsonl"), "GOOD\n") << source;
  }
}

// Finding 7: a pressed reference and a viewer on every interface are warned of; the run goes on.
TEST(CliReliability, APressedReferenceIsWarnedOf) {
  const std::string dir = test::temp_folder("cli_pressed_reference");
  ASSERT_EQ(run_emit("simulate --press 30,30,5,10 --out " + dir + "/pressed.csv").exit_code, 0);
  const auto r = run_emit("reconstruct --method paper --reference " + dir + "/pressed.csv --frames " + dir +
                          "/pressed.csv --contacts " + dir + "/c.jsonl --cache " + dir + "/cache");
  EXPECT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.err.find("emit: warning: " + dir + "/pressed.csv: the reference reads up to"), std::string::npos)
      << r.err;
  EXPECT_NE(r.err.find("was the sheet pressed?"), std::string::npos) << r.err;
}

TEST(CliReliability, AViewerOnEveryInterfaceIsWarnedOf) {
  const std::string dir = test::temp_folder("cli_serve_all");
  const auto r = run_emit("live --method paper --source sim --frames 2 --serve 0.0.0.0:0 --cache " + dir);
  EXPECT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.err.find("emit: warning: --serve 0.0.0.0:0: the viewer is open to every computer"), std::string::npos)
      << r.err;
}

// Finding 8: --threads after the command was "not expected".
TEST(CliReliability, ThreadsAfterTheCommand) {
  const std::string dir = test::temp_folder("cli_threads_after");
  const auto r = run_emit("mesh --out " + dir + "/m.msh --threads 2");
  EXPECT_EQ(r.exit_code, 0) << r.err;
  EXPECT_TRUE(fs::exists(dir + "/m.msh"));
}

}  // namespace
}  // namespace emit
