// `emit live` never hides a failure (issue 32: a failed simulator ended it with a normal summary
// and exit 0). Run as a user runs it, each failure ends the run with exit 1 and its message on
// the last line, after the summary of what was done; the files it wrote stay as PATH.partial
// (whole: the recording's packets, the MCAP file with its footer, the contacts' lines) and the
// files they would have replaced are untouched. The failing source is a recording: one cut
// mid-packet (a crashed run's) and one corrupt mid-run stand for a source that fails after frames
// came (the simulator no longer fails on the built-in sheets: tests/twin/sim_scripts_on_sheets_test.cpp);
// then a serial port removed for good, and a writer that fails.
#include <fcntl.h>
#include <spawn.h>
#include <sys/stat.h>
#include <sys/sysmacros.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <csignal>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <memory>
#include <string>
#include <thread>
#include <vector>

#include <gtest/gtest.h>

#include "emit/acquire/file_source.hpp"
#include "emit/sensor/sensor_json.hpp"
#include "pseudo_terminal.hpp"
#include "test_support.hpp"

extern char** environ;

namespace emit {
namespace {

namespace fs = std::filesystem;
using test::run_emit;

constexpr std::size_t header_bytes = 32, packet_bytes = 532;  // a recording's, 16 electrodes (docs/recording.md)

std::string cache() { return " --cache " + test::temp_folder("cli_live_failure_cache"); }

std::string last_line(const std::string& text) {
  const std::size_t end = text.find_last_not_of('\n');
  if (end == std::string::npos) return "";
  const std::size_t start = text.rfind('\n', end);
  const std::size_t first = start == std::string::npos ? 0 : start + 1;
  return text.substr(first, end + 1 - first);
}

std::string bytes_of(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

void write_file(const std::string& path, const std::string& bytes) { std::ofstream(path, std::ios::binary) << bytes; }

/// A recording of 30 frames of the twin (10 for the reference, 20 of a press held at 30, 30).
std::string thirty_frames(const std::string& dir) {
  const std::string path = dir + "/rec.emitrec";
  const auto r =
      run_emit("live --method paper --source sim:fixed:30,30,10 --fps 0 --frames 20 --record " + path + cache());
  EXPECT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(fs::file_size(path), header_bytes + 30 * packet_bytes);
  return bytes_of(path);
}

std::size_t lines_in(const std::string& path) {
  const std::string text = test::read_text(path);
  return static_cast<std::size_t>(std::count(text.begin(), text.end(), '\n'));
}

// A recording cut 100 bytes into its last packet: its 29 whole frames replay (10 for the
// reference, 19 reconstructed), then exit 1 naming the file, the frame and the byte
// (32 + 29·532 = 15460). The contacts and the new recording stay .partial, the good ones untouched.
TEST(CliLiveFailure, ARecordingCutMidPacketEndsWithItsMessage) {
  const std::string dir = test::temp_folder("cli_live_cut");
  const std::string whole = thirty_frames(dir);
  const std::string cut = dir + "/cut.emitrec";
  write_file(cut, whole.substr(0, whole.size() - 100));
  write_file(dir + "/c.jsonl", "GOOD\n");
  write_file(dir + "/again.emitrec", "OLD");
  const auto r = run_emit("live --method paper --source file:" + cut + " --fps 0 --contacts " + dir +
                          "/c.jsonl --record " + dir + "/again.emitrec" + cache());
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_EQ(last_line(r.err), "emit: " + cut + ": truncated: frame 29 (byte 15460) has 432 of its 532 bytes") << r.err;
  EXPECT_NE(r.out.find("live: 19 frames in "), std::string::npos) << r.out;
  EXPECT_NE(r.err.find("emit: the run failed; what it wrote is kept in " + dir + "/c.jsonl.partial, " + dir +
                       "/again.emitrec.partial (the files it would have replaced are untouched)"),
            std::string::npos)
      << r.err;
  EXPECT_EQ(test::read_text(dir + "/c.jsonl"), "GOOD\n");
  EXPECT_EQ(test::read_text(dir + "/again.emitrec"), "OLD");
  EXPECT_EQ(lines_in(dir + "/c.jsonl.partial"), 19u);
  // Every frame the run read, recorded whole: the cut recording without its cut.
  EXPECT_EQ(fs::file_size(dir + "/again.emitrec.partial"), header_bytes + 29 * packet_bytes);
  FileSource replay(dir + "/again.emitrec.partial", default_sensor(), true);
  EXPECT_EQ(replay.frame_count(), 29u);
}

// A source that fails mid-run, after frames came: frame 15 of the recording corrupt (a payload
// bit flipped). Exit 1 with the source's message, after 5 reconstructed frames; the MCAP file is
// closed whole (its footer and magic) at PATH.partial, PATH not made.
TEST(CliLiveFailure, ASourceThatFailsMidRunEndsWithItsMessage) {
  const std::string dir = test::temp_folder("cli_live_corrupt");
  std::string bytes = thirty_frames(dir);
  bytes[header_bytes + 15 * packet_bytes + 100] ^= 0x04;
  const std::string corrupt = dir + "/corrupt.emitrec";
  write_file(corrupt, bytes);
  const auto r =
      run_emit("live --method paper --source file:" + corrupt + " --fps 0 --mcap " + dir + "/m.mcap" + cache());
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_EQ(last_line(r.err), "emit: " + corrupt + ": frame 15 (byte 8012) is not a valid packet (sync, header or CRC)")
      << r.err;
  EXPECT_NE(r.out.find("live: 5 frames in "), std::string::npos) << r.out;
  EXPECT_FALSE(fs::exists(dir + "/m.mcap"));
  const std::string mcap = bytes_of(dir + "/m.mcap.partial");
  ASSERT_GT(mcap.size(), 8u);
  EXPECT_EQ(mcap.substr(mcap.size() - 8), std::string("\x89MCAP0\r\n", 8));
}

// The board's port removed for good (a pty whose other end is closed: its node goes): retried
// every 0.5 s for --reconnect-s 1, then exit 1 with the port's message.
TEST(CliLiveFailure, ASerialPortRemovedForGoodEndsWithItsMessage) {
  const std::string dir = test::temp_folder("cli_live_serial_gone");
  auto pty = std::make_unique<test::PseudoTerminal>();
  ::fcntl(pty->master(), F_SETFD, FD_CLOEXEC);  // emit must not hold the board's end open itself
  const std::string port = pty->slave_path();
  int out[2];
  ASSERT_EQ(::pipe2(out, O_CLOEXEC), 0);
  const std::vector<std::string> arguments = {test::cli_path(), "live",
                                              "--method",       "paper",
                                              "--source",       "serial:" + port,
                                              "--reconnect-s",  "1",
                                              "--cache",        test::temp_folder("cli_live_failure_cache")};
  std::vector<char*> argv;
  argv.reserve(arguments.size() + 1);
  for (const std::string& a : arguments) argv.push_back(const_cast<char*>(a.c_str()));
  argv.push_back(nullptr);
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_adddup2(&actions, out[1], 1);
  posix_spawn_file_actions_addopen(&actions, 2, (dir + "/stderr").c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
  pid_t child = 0;
  ASSERT_EQ(posix_spawn(&child, argv[0], &actions, nullptr, argv.data(), environ), 0);
  posix_spawn_file_actions_destroy(&actions);
  ::close(out[1]);
  // The port is open and the models built once emit says it is reconstructing.
  std::string said;
  char buffer[256];
  for (ssize_t n;
       said.find("reconstructing with") == std::string::npos && (n = ::read(out[0], buffer, sizeof buffer)) > 0;)
    said.append(buffer, static_cast<std::size_t>(n));
  ASSERT_NE(said.find("reconstructing with"), std::string::npos) << said << test::read_text(dir + "/stderr");
  const auto pulled = std::chrono::steady_clock::now();
  pty.reset();  // removed, never to come back
  int status = 0;
  while (::waitpid(child, &status, WNOHANG) == 0) {  // a minute at most: a run that never ends fails, not hangs
    if (std::chrono::steady_clock::now() - pulled > std::chrono::seconds(60)) {
      ::kill(child, SIGKILL);
      ::waitpid(child, &status, 0);
      FAIL() << "emit went on after its port was removed for good";
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  }
  for (ssize_t n; (n = ::read(out[0], buffer, sizeof buffer)) > 0;) said.append(buffer, static_cast<std::size_t>(n));
  ::close(out[0]);
  const double after_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - pulled).count();
  ASSERT_TRUE(WIFEXITED(status));
  EXPECT_EQ(WEXITSTATUS(status), 1);
  const std::string err = test::read_text(dir + "/stderr");
  EXPECT_EQ(last_line(err).rfind("emit: serial:" + port + " at 921600 baud: disconnected for 1 s and not back (", 0),
            0u)
      << err;
  EXPECT_NE(said.find("live: 0 frames in "), std::string::npos) << said;
  // Not before its reconnection time; the rest is a retry (0.5 s), a poll and the exit.
  EXPECT_GE(after_s, 1.0);
  EXPECT_LT(after_s, 10.0);
}

// A writer that fails (a full device as --contacts; mknod needs root): exit 1 with its message at
// the first reconstructed frame; the recording keeps every frame read (10 for the reference and
// the one whose contacts failed) at PATH.partial, and the good PATH is untouched.
TEST(CliLiveFailure, AWriterThatFailsEndsTheRun) {
  if (::geteuid() != 0) GTEST_SKIP() << "mknod needs root";
  const std::string dir = test::temp_folder("cli_live_writer");
  const std::string full = dir + "/full";
  ASSERT_EQ(::mknod(full.c_str(), S_IFCHR | 0666, makedev(1, 7)), 0);  // /dev/full's numbers
  write_file(dir + "/rec.emitrec", "OLD");
  const auto r = run_emit("live --method paper --source sim:fixed:30,30 --fps 0 --frames 20 --contacts " + full +
                          " --record " + dir + "/rec.emitrec" + cache());
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_EQ(last_line(r.err), "emit: --contacts " + full + ": write failed (No space left on device)") << r.err;
  EXPECT_NE(r.out.find("live: 0 frames in "), std::string::npos) << r.out;
  EXPECT_EQ(test::read_text(dir + "/rec.emitrec"), "OLD");
  EXPECT_EQ(fs::file_size(dir + "/rec.emitrec.partial"), header_bytes + 11 * packet_bytes);
}

// The reconnection time is a positive number of seconds, refused on the command line otherwise.
TEST(CliLiveFailure, AReconnectionTimeMustBePositive) {
  for (const std::string value : {"0", "-1", "x"}) {
    const auto r = run_emit("live --source sim --reconnect-s " + value);
    EXPECT_EQ(r.exit_code, 2);
    EXPECT_EQ(r.err,
              "emit: --reconnect-s: must be a positive number, got \"" + value + "\" (see 'emit live --help')\n");
  }
}

}  // namespace
}  // namespace emit
