// `emit export` run as a user runs it (suite Cli, with the other end-to-end runs): a live run's
// recording of the twin turned into frames, a reference, contacts and MCAP; and bad input, each
// case one line on stderr, exit 1 (2 for a command line CLI11 refuses), no good file replaced.
#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "emit/acquire/recorder.hpp"
#include "emit/io/contacts_jsonl.hpp"
#include "emit/io/frames_csv.hpp"
#include "emit/sensor/sensor_json.hpp"
#include "test_support.hpp"

namespace emit {
namespace {

namespace fs = std::filesystem;
using test::run_emit;

int lines_in(const std::string& text) { return static_cast<int>(std::count(text.begin(), text.end(), '\n')); }

// The twin holds a press at (20, 40) from its 16th frame (of 30: 10 captured as the reference,
// then 20): exported, every frame is in the frames file, the first 10 in the reference, and the
// contacts find the press on frames 15..29 only, within 0.5 mm (live_loop_test's bound for the
// same source; README: fit's p95 0.13 mm), each line with the board's time, later than the last;
// the tracks CSV has the touch's 15 rows.
TEST(Cli, ExportTurnsALiveRecordingIntoFramesContactsAndMcap) {
  const std::string d = test::temp_folder("cli_export");
  auto r = run_emit("live --source sim:fixed:20,40 --frames 20 --fps 0 --record " + d + "/r.emitrec --cache " + d);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  r = run_emit("export " + d + "/r.emitrec --frames " + d + "/f.csv --reference " + d + "/ref.csv --contacts " + d +
               "/c.jsonl --tracks " + d + "/t.csv --mcap " + d + "/c.mcap --cache " + d);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("exported 30 frames ("), std::string::npos) << r.out;
  EXPECT_NE(r.out.find(", 0 missed)"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("reference: " + d + "/ref.csv (the first 10 frames)"), std::string::npos) << r.out;
  EXPECT_EQ(read_frames_csv(d + "/f.csv", 16).size(), 30u);
  EXPECT_EQ(read_frames_csv(d + "/ref.csv", 16).size(), 10u);
  std::istringstream lines(test::read_text(d + "/c.jsonl"));
  long expected = 0;
  double last_board_s = -1;
  for (std::string line; std::getline(lines, line); ++expected) {
    const ContactsLine read = parse_contacts_record(line);
    EXPECT_EQ(read.frame, expected);
    EXPECT_GT(read.times.board_s, last_board_s) << line;
    last_board_s = read.times.board_s;
    if (expected < 15) {
      EXPECT_TRUE(read.contacts.empty()) << line;
      continue;
    }
    ASSERT_EQ(read.contacts.size(), 1u) << line;
    EXPECT_LT(std::hypot(read.contacts[0].x_mm - 20, read.contacts[0].y_mm - 40), 0.5) << line;
    EXPECT_EQ(read.contacts[0].id, 0);  // one touch, held
  }
  EXPECT_EQ(expected, 30);
  const std::string tracks = test::read_text(d + "/t.csv");
  EXPECT_EQ(tracks.substr(0, tracks.find(',')), "time_s");
  EXPECT_EQ(lines_in(tracks), 1 + 15);  // the header, then the touch on each of frames 15..29
  EXPECT_EQ(test::read_text(d + "/c.mcap").substr(1, 4), "MCAP");
  for (const std::string name : {"f.csv", "ref.csv", "c.jsonl", "t.csv", "c.mcap"})
    EXPECT_FALSE(fs::exists(d + "/" + name + ".partial")) << name;
  // README's third line: reconstruct on the exported files finds the same contacts.
  r = run_emit("reconstruct --reference " + d + "/ref.csv --frames " + d + "/f.csv --contacts " + d +
               "/again.jsonl --cache " + d);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  std::istringstream exported(test::read_text(d + "/c.jsonl")), again(test::read_text(d + "/again.jsonl"));
  for (std::string a, b; std::getline(exported, a) && std::getline(again, b);) {
    const std::vector<Contact> x = parse_contacts_line(a), y = parse_contacts_line(b);
    ASSERT_EQ(x.size(), y.size()) << a << "\n" << b;
    for (std::size_t c = 0; c < x.size(); ++c) EXPECT_EQ(x[c].x_mm, y[c].x_mm) << a << "\n" << b;
  }
}

TEST(Cli, ExportRefusesBadInputInOneLine) {
  const std::string d = test::temp_folder("cli_export_bad");
  const Sensor sensor = default_sensor();
  {
    Recorder recorder(d + "/r.emitrec", sensor);
    RawFrame raw;
    raw.electrode_count = 16;
    raw.adc_bits = 12;
    raw.oversampling = 1;
    raw.counts.assign(256, 100);
    for (std::uint32_t k = 0; k < 12; ++k) {
      raw.sequence = k;
      raw.timestamp_us = 20'000 * k;
      recorder.record(raw);
    }
  }
  std::ofstream(d + "/good.csv") << "good\n";
  const auto refused = [&](const std::string& arguments, const std::string& message, int exit_code = 1) {
    const auto r = run_emit("export " + arguments);
    EXPECT_EQ(r.exit_code, exit_code) << arguments << "\n" << r.err;
    EXPECT_EQ(lines_in(r.err), 1) << arguments << "\n" << r.err;
    EXPECT_NE(r.err.find(message), std::string::npos) << arguments << "\n" << r.err;
    EXPECT_EQ(test::read_text(d + "/good.csv"), "good\n") << arguments;
  };
  refused(d + "/missing.emitrec --frames " + d + "/good.csv",
          "emit: " + d + "/missing.emitrec: cannot open the recording");
  refused(d + "/good.csv --frames " + d + "/x.csv", d + "/good.csv: not an emit recording");
  refused(d + "/r.emitrec", "emit: nothing to export: give --frames, --reference, --contacts, --tracks or --mcap");
  refused(d + "/r.emitrec --frames " + d + "/r.emitrec", "is the same file as the recording");
  refused(d + "/r.emitrec --frames " + d + "/good.csv --calibration " + d + "/good.csv",
          "--calibration " + d + "/good.csv: only --contacts, --tracks and --mcap reconstruct frames");
  refused(d + "/r.emitrec --frames " + d + "/good.csv --reference-frames 0", "--reference-frames", 2);
  refused("--frames " + d + "/good.csv", "recording is required", 2);
  refused(d + "/r.emitrec --frames " + d + "/good.csv --sensor " +
              test::source_path("examples/sensors/square120_32.json"),
          "r.emitrec: recorded with 16 electrodes, but the sensor has 32");
  // Cut 200 bytes into its 11th packet (a crashed run's): the 10 whole frames kept beside.
  fs::copy_file(d + "/r.emitrec", d + "/cut.emitrec");
  fs::resize_file(d + "/cut.emitrec", 32 + 10 * 532 + 200);
  refused(d + "/cut.emitrec --frames " + d + "/good.csv",
          "cut.emitrec: truncated: frame 10 (byte 5352) has 200 of its 532 bytes; the 10 frames before it exported "
          "to " +
              d + "/good.csv.partial");
  EXPECT_EQ(read_frames_csv(d + "/good.csv.partial", 16).size(), 10u);
  fs::remove(d + "/good.csv.partial");
  // A packet corrupt mid-file (its CRC): the frames before it kept, the packet named.
  fs::copy_file(d + "/r.emitrec", d + "/bad.emitrec");
  {
    std::fstream bad(d + "/bad.emitrec", std::ios::in | std::ios::out | std::ios::binary);
    bad.seekp(32 + 5 * 532 + 100);
    bad.put('\x7f');
  }
  refused(d + "/bad.emitrec --frames " + d + "/good.csv",
          "bad.emitrec: frame 5 (byte 2692) is not a valid packet (sync, header or CRC); the 5 frames before it "
          "exported");
  EXPECT_EQ(read_frames_csv(d + "/good.csv.partial", 16).size(), 5u);
  EXPECT_FALSE(fs::exists(d + "/x.csv"));
  EXPECT_FALSE(fs::exists(d + "/x.csv.partial"));
}

}  // namespace
}  // namespace emit
