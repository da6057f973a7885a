// End to end, the cases of docs/bad-input.md that need more than one bad command line
// (cli_test.cpp's CliBadInput holds the rest): a signal mid-run, a failing live source, warnings
// that let the run go on, options after the command, and outputs that are devices, FIFOs and
// pipes whose reader goes away. Devices are private nodes made with mknod in a temporary folder
// (root only), never the machine's own /dev/null or /dev/full.
#include <fcntl.h>
#include <spawn.h>
#include <sys/stat.h>
#include <sys/sysmacros.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <csignal>
#include <filesystem>
#include <fstream>
#include <regex>
#include <set>
#include <thread>
#include <vector>

#include <gtest/gtest.h>

#include "emit/acquire/file_source.hpp"
#include "emit/sensor/sensor_json.hpp"
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

/// Starts emit with `arguments` (after the program), standard output into `stdout_fd` (or
/// nowhere), standard error into a file. \return its process id.
pid_t spawn_emit(const std::vector<std::string>& arguments, int stdout_fd, const std::string& stderr_path) {
  std::vector<std::string> all = {test::cli_path()};
  all.insert(all.end(), arguments.begin(), arguments.end());
  std::vector<char*> argv;
  argv.reserve(all.size() + 1);
  for (const std::string& a : all) argv.push_back(const_cast<char*>(a.c_str()));
  argv.push_back(nullptr);
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  if (stdout_fd >= 0) posix_spawn_file_actions_adddup2(&actions, stdout_fd, 1);
  else posix_spawn_file_actions_addopen(&actions, 1, "/dev/null", O_WRONLY, 0);  // read only by the system
  posix_spawn_file_actions_addopen(&actions, 2, stderr_path.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
  pid_t child = 0;
  const int spawned = posix_spawn(&child, argv[0], &actions, nullptr, argv.data(), environ);
  posix_spawn_file_actions_destroy(&actions);
  return spawned == 0 ? child : -1;
}

/// The exit code, or 128 + the signal that ended it.
int wait_for(pid_t child) {
  int status = 0;
  if (::waitpid(child, &status, 0) != child) return -1;
  return WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
}

bool is_character_device(const std::string& path) {
  struct stat status {};
  return ::lstat(path.c_str(), &status) == 0 && S_ISCHR(status.st_mode);
}

std::string last_line(const std::string& text) {
  const std::size_t end = text.find_last_not_of('\n');
  if (end == std::string::npos) return "";
  const std::size_t start = text.rfind('\n', end);
  return text.substr(start == std::string::npos ? 0 : start + 1,
                     end + 1 - (start == std::string::npos ? 0 : start + 1));
}

std::set<std::string> names_in(const std::string& folder) {
  std::set<std::string> names;
  for (const auto& entry : fs::directory_iterator(folder)) names.insert(entry.path().filename().string());
  return names;
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
  while (!fs::exists(dir + "/images/frame_000003.png") && std::chrono::steady_clock::now() < deadline)
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

// Every write-then-rename output renamed its temporary file over the target: as root, an output
// that was a device became a regular file, and a write into a full device "succeeded" (exit 0).
TEST(CliReliability, OutputsThatAreDevicesAreWrittenIntoNotReplaced) {
  if (::geteuid() != 0) GTEST_SKIP() << "mknod needs root";
  const std::string dir = test::temp_folder("cli_devices");
  const std::string null = dir + "/null", full = dir + "/full", cache = " --cache " + dir + "/cache";
  ASSERT_EQ(::mknod(null.c_str(), S_IFCHR | 0666, makedev(1, 3)), 0);  // /dev/null's numbers
  ASSERT_EQ(::mknod(full.c_str(), S_IFCHR | 0666, makedev(1, 7)), 0);  // /dev/full's
  auto r = run_emit("simulate --press 30,30,5,10 --out " + null + " --truth " + dir + "/t.csv");
  EXPECT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(test::read_text(dir + "/t.csv").rfind("frame,x_mm,y_mm", 0), 0u);
  r = run_emit("simulate --press 30,30,5,10 --out " + full + " --truth " + dir + "/t2.csv");
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_EQ(last_line(r.err), "emit: --out " + full + ": write failed (No space left on device)") << r.err;
  EXPECT_FALSE(fs::exists(dir + "/t2.csv"));
  r = run_emit("simulate --press 30,30,5,10 --out " + null);  // the presses would go beside it
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_EQ(r.err, "emit: --out " + null + " is not a regular file: give --truth too (by default the presses go " +
                       "beside --out)\n");
  ASSERT_EQ(run_emit("simulate --press 30,30,5,10 --out " + dir + "/f.csv").exit_code, 0);
  const std::string frames = " --reference " + dir + "/f.csv --frames " + dir + "/f.csv";
  r = run_emit("reconstruct --method paper" + frames + " --contacts " + null + " --mcap " + null + cache);
  EXPECT_EQ(r.exit_code, 0) << r.err;
  r = run_emit("reconstruct --method paper" + frames + " --contacts " + full + cache);
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_EQ(last_line(r.err), "emit: --contacts " + full + ": write failed (No space left on device)") << r.err;
  const std::string live = "live --method paper --source sim --fps 0 --frames 3" + cache;
  r = run_emit(live + " --contacts " + null + " --record " + null + " --mcap " + null);
  EXPECT_EQ(r.exit_code, 0) << r.err;
  r = run_emit(live + " --record " + full);
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_EQ(last_line(r.err), "emit: --record " + full + ": write failed (No space left on device)") << r.err;
  // Gmsh writes only files it names, by their extension: a scratch file, copied into the device.
  r = run_emit("mesh --element-size-mm 6 --out " + null);
  EXPECT_EQ(r.exit_code, 0) << r.err;
  r = run_emit("mesh --element-size-mm 6 --out " + full);
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_EQ(last_line(r.err), "emit: --out " + full + ": write failed (No space left on device)") << r.err;
  EXPECT_TRUE(is_character_device(null));
  EXPECT_TRUE(is_character_device(full));
  EXPECT_EQ(names_in(dir), (std::set<std::string>{"cache", "f.csv", "f_presses.csv", "full", "null", "t.csv"}));
}

// `emit live` truncated an existing --contacts file, then failed on --mcap (a folder left where
// its .partial goes, or a name too long once ".partial" is added): exit 1 and 9,907 bytes gone.
TEST(CliReliability, ALiveOutputThatCannotBeOpenedTouchesNoOther) {
  const std::string dir = test::temp_folder("cli_live_outputs");
  std::ofstream(dir + "/c.jsonl") << "GOOD\n";
  std::ofstream(dir + "/rec.emitrec") << "OLD";
  fs::create_directory(dir + "/x.mcap.partial");
  const std::string live = "live --method paper --source sim --fps 0 --frames 3 --cache " +
                           test::temp_folder("cli_live_outputs_cache") + " --contacts " + dir + "/c.jsonl --record " +
                           dir + "/rec.emitrec --mcap ";
  auto r = run_emit(live + dir + "/x.mcap");
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_EQ(r.err, "emit: --mcap " + dir + "/x.mcap: cannot create " + dir + "/x.mcap.partial (Is a directory)\n");
  const std::string long_name = dir + "/" + std::string(250, 'y') + ".mcap";
  r = run_emit(live + long_name);
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_NE(r.err.find("emit: --mcap " + long_name + ": cannot create " + long_name + ".partial (File name too long)"),
            std::string::npos)
      << r.err;
  EXPECT_EQ(test::read_text(dir + "/c.jsonl"), "GOOD\n");
  EXPECT_EQ(test::read_text(dir + "/rec.emitrec"), "OLD");
  EXPECT_EQ(names_in(dir), (std::set<std::string>{"c.jsonl", "rec.emitrec", "x.mcap.partial"}));
}

// SIGPIPE killed `emit live ... --contacts - | head -c 100` silently (exit 141), the recording a
// 0-byte .partial, the MCAP without its footer. Now the run ends as a stop does: a one-line note,
// both recordings closed and renamed into place, exit 0.
TEST(CliReliability, LiveEndsCleanlyWhenTheContactsReaderGoesAway) {
  const std::string dir = test::temp_folder("cli_live_reader_gone");
  int ends[2];
  ASSERT_EQ(::pipe2(ends, O_CLOEXEC), 0);  // emit gets only the end it is given
  const pid_t child =
      spawn_emit({"live", "--method", "paper", "--source", "sim", "--fps", "0", "--seconds", "120", "--cache",
                  dir + "/cache", "--contacts", "-", "--record", dir + "/P.emitrec", "--mcap", dir + "/P.mcap"},
                 ends[1], dir + "/stderr");
  ASSERT_GT(child, 0);
  ::close(ends[1]);
  char bytes[100];
  std::size_t got = 0;
  for (ssize_t n; got < sizeof bytes && (n = ::read(ends[0], bytes + got, sizeof bytes - got)) > 0;)
    got += static_cast<std::size_t>(n);
  EXPECT_EQ(got, sizeof bytes);
  ::close(ends[0]);  // as `head -c 100` does
  EXPECT_EQ(wait_for(child), 0);
  const std::string err = test::read_text(dir + "/stderr");
  EXPECT_NE(err.find("emit: the reader of --contacts - went away; stopped after "), std::string::npos) << err;
  EXPECT_FALSE(fs::exists(dir + "/P.emitrec.partial"));
  EXPECT_FALSE(fs::exists(dir + "/P.mcap.partial"));
  // The recording replays, every frame of it (the reference's capture included).
  std::smatch said;
  ASSERT_TRUE(std::regex_search(err, said, std::regex("\nrecorded ([0-9]+) frames to "))) << err;
  const long recorded = std::stol(said[1].str());
  EXPECT_GT(recorded, 10);
  FileSource replay(dir + "/P.emitrec", default_sensor(), true);
  long replayed = 0;
  for (SourceFrame frame; !replay.finished();) replayed += replay.next(frame, std::chrono::milliseconds(0));
  EXPECT_EQ(replayed, recorded);
  const std::string mcap = test::read_text(dir + "/P.mcap");  // ends with its footer and magic
  ASSERT_GT(mcap.size(), 8u);
  EXPECT_EQ(mcap.substr(mcap.size() - 8), std::string("\x89MCAP0\r\n", 8));
}

// Ctrl-C while the contacts' reader does not read: the write that waited for it is given up, and
// the run stops as a stop does (it waited in the write, the stop flag unseen, until SIGKILL).
TEST(CliReliability, CtrlCStopsLiveWhileTheContactsReaderDoesNotRead) {
  const std::string dir = test::temp_folder("cli_live_stuck_reader");
  int ends[2];
  ASSERT_EQ(::pipe2(ends, O_CLOEXEC), 0);
  ASSERT_GT(::fcntl(ends[1], F_SETPIPE_SZ, 4096), 0);  // full after a few lines
  const pid_t child = spawn_emit({"live", "--method", "paper", "--source", "sim", "--fps", "0", "--seconds", "120",
                                  "--cache", dir + "/cache", "--contacts", "-", "--record", dir + "/P.emitrec"},
                                 ends[1], dir + "/stderr");
  ASSERT_GT(child, 0);
  ::close(ends[1]);
  const std::string wchan = "/proc/" + std::to_string(child) + "/wchan";
  bool waiting = false;  // in the kernel's pipe write: the pipe is full
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(60);
  while (!waiting && std::chrono::steady_clock::now() < deadline) {
    std::this_thread::sleep_for(std::chrono::milliseconds(50));
    waiting = test::read_text(wchan).find("pipe_write") != std::string::npos;
  }
  ASSERT_TRUE(waiting) << test::read_text(dir + "/stderr");
  ::kill(child, SIGINT);
  EXPECT_EQ(wait_for(child), 0);
  ::close(ends[0]);
  EXPECT_NE(test::read_text(dir + "/stderr").find(" contacts lines dropped while no one read --contacts -"),
            std::string::npos);
  EXPECT_TRUE(fs::exists(dir + "/P.emitrec"));
  EXPECT_FALSE(fs::exists(dir + "/P.emitrec.partial"));
}

// `emit reconstruct --contacts -` into a pipe no one reads: the failed write named, exit 1 (a
// batch result not delivered whole is an error, as GNU tools say "write error: Broken pipe").
TEST(CliReliability, ReconstructIntoAPipeNoOneReadsSaysSo) {
  const std::string dir = test::temp_folder("cli_reconstruct_pipe");
  ASSERT_EQ(run_emit("simulate --press 30,30,5,10 --out " + dir + "/f.csv").exit_code, 0);
  int ends[2];
  ASSERT_EQ(::pipe2(ends, O_CLOEXEC), 0);  // emit gets only the end it is given
  ::close(ends[0]);
  const pid_t child = spawn_emit({"reconstruct", "--method", "paper", "--reference", dir + "/f.csv", "--frames",
                                  dir + "/f.csv", "--contacts", "-", "--cache", dir + "/cache"},
                                 ends[1], dir + "/stderr");
  ASSERT_GT(child, 0);
  ::close(ends[1]);
  EXPECT_EQ(wait_for(child), 1);
  EXPECT_EQ(last_line(test::read_text(dir + "/stderr")), "emit: --contacts -: write failed (Broken pipe)");
  EXPECT_FALSE(fs::exists("-"));
}

// A FIFO is a port readers come and go at: while none reads, lines are dropped (and counted); the
// next reader gets what the last one left unread in the pipe, then whole lines to the end.
TEST(CliReliability, AContactsFifosReaderMayLeaveAndAnotherTakeOver) {
  const std::string dir = test::temp_folder("cli_live_fifo");
  const std::string fifo = dir + "/contacts.fifo";
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
  const pid_t child = spawn_emit({"live", "--method", "paper", "--source", "sim", "--fps", "50", "--frames", "60",
                                  "--cache", dir + "/cache", "--contacts", fifo},
                                 -1, dir + "/stderr");
  ASSERT_GT(child, 0);
  const auto frames_in = [](const std::string& text) {
    std::vector<long> frames;
    for (std::size_t at = 0; (at = text.find("{\"frame\": ", at)) != std::string::npos; ++at)
      if (text.find('\n', at) != std::string::npos) frames.push_back(std::stol(text.substr(at + 10)));
    return frames;
  };
  std::string first;
  int reader = ::open(fifo.c_str(), O_RDONLY);  // waits for emit to open it
  ASSERT_GE(reader, 0);
  char bytes[4096];
  for (ssize_t n; frames_in(first).size() < 3 && (n = ::read(reader, bytes, sizeof bytes)) > 0;)
    first.append(bytes, static_cast<std::size_t>(n));
  ::close(reader);
  std::this_thread::sleep_for(std::chrono::milliseconds(300));  // ~15 frames with no reader
  reader = ::open(fifo.c_str(), O_RDONLY);
  ASSERT_GE(reader, 0);
  std::string second;
  for (ssize_t n; (n = ::read(reader, bytes, sizeof bytes)) > 0;) second.append(bytes, static_cast<std::size_t>(n));
  ::close(reader);
  EXPECT_EQ(wait_for(child), 0);
  std::vector<long> frames = frames_in(first);
  ASSERT_GE(frames.size(), 3u);
  const std::vector<long> after = frames_in(second);
  ASSERT_GE(after.size(), 10u);
  frames.insert(frames.end(), after.begin(), after.end());
  int gaps = 0;
  for (std::size_t k = 1; k < frames.size(); ++k) {
    EXPECT_GT(frames[k], frames[k - 1]);
    gaps += frames[k] > frames[k - 1] + 1;
  }
  EXPECT_EQ(gaps, 1) << "one run of frames dropped while no one read";
  EXPECT_EQ(frames.back(), 69);  // the last frame: 10 for the reference's capture, then 60
  const std::string err = test::read_text(dir + "/stderr");
  EXPECT_NE(err.find(" contacts lines dropped while no one read --contacts " + fifo), std::string::npos) << err;
}

}  // namespace

// `emit calibrate --capture` (issue 33): Ctrl-C during the finger presses keeps what was captured,
// complete (the reference and the presses found so far), says how to calibrate from it offline,
// and exits 130 as a shell's Ctrl-C does. A source spec that is wrong is refused before anything.
TEST(CliReliability, CaptureStoppedByCtrlCKeepsWhatItCaptured) {
  const std::string dir = test::temp_folder("cli_capture_sigint");
  const pid_t child = spawn_emit({"calibrate", "--sensor", test::source_path("examples/sensors/square30.json"),
                                  "--capture", "sim:calibration", "--fps", "50", "--out", dir + "/calibration.json"},
                                 -1, dir + "/stderr");
  ASSERT_GT(child, 0);
  const std::string presses = dir + "/calibration_capture/presses.csv";
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(120);
  while (!fs::exists(presses) && std::chrono::steady_clock::now() < deadline)
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  ASSERT_TRUE(fs::exists(presses)) << test::read_text(dir + "/stderr");
  ::kill(child, SIGINT);
  EXPECT_EQ(wait_for(child), 130);
  const std::string err = test::read_text(dir + "/stderr");
  EXPECT_NE(err.find("stopped at press "), std::string::npos) << err;
  EXPECT_NE(err.find("; calibrate from them with: emit calibrate --sensor "), std::string::npos) << err;
  const std::string text = test::read_text(presses);
  EXPECT_EQ(text.rfind("frame,x_mm,y_mm,radius_mm,force_N,pressure_N_per_mm2\n0,,,5.0000,,\n", 0), 0u) << text;
  EXPECT_FALSE(fs::exists(dir + "/calibration.json"));
  // A recording that ends before the person is done: what was kept, then the end as an error.
  ASSERT_EQ(run_emit("live --source sim:calibration:1 --fps 0 --frames 110 --contacts /dev/null --record " + dir +
                     "/short.emitrec")
                .exit_code,
            0);
  const auto ended = run_emit("calibrate --capture file:" + dir + "/short.emitrec --fps 0 --out " + dir + "/e.json");
  EXPECT_EQ(ended.exit_code, 1);
  EXPECT_NE(ended.err.find(": kept the reference and 1 finger presses, 0 weights in " + dir + "/e_capture"),
            std::string::npos)
      << ended.err;
  EXPECT_NE(ended.err.find("emit: --capture file:" + dir + "/short.emitrec: the source ended after "),
            std::string::npos)
      << ended.err;
  const auto r = run_emit("calibrate --capture bogus: --out " + dir + "/c.json");
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_NE(r.err.find("emit: "), std::string::npos) << r.err;
}

}  // namespace emit
