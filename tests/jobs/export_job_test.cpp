// `emit export`'s job (jobs/export_job.hpp) in-process: a recording's frames come back from the
// frames CSV as the recording holds them; a cut recording exports its whole frames to PATH.partial,
// fails naming the cut and leaves a good PATH alone; what is not a recording is refused with
// nothing written; the contacts are the reconstruct job's on the exported files, with board times.
#include "emit/jobs/export_job.hpp"

#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "emit/acquire/file_source.hpp"
#include "emit/acquire/recorder.hpp"
#include "emit/core/errors.hpp"
#include "emit/io/contacts_jsonl.hpp"
#include "emit/io/frames_csv.hpp"
#include "emit/jobs/reconstruct_job.hpp"
#include "emit/sensor/adc.hpp"
#include "emit/sensor/sensor_json.hpp"
#include "emit/twin/twin.hpp"
#include "test_support.hpp"

namespace emit {
namespace {

namespace fs = std::filesystem;

/// A board's packet of `volts` as the ADC codes them, frame k at 50 frames/s from board time 3 s.
RawFrame packet_of(const Sensor& sensor, const Frame& volts, std::uint32_t k) {
  RawFrame raw;
  raw.electrode_count = sensor.electrode_count();
  raw.adc_bits = sensor.adc.bits;
  raw.oversampling = 1;
  raw.sequence = k;
  raw.timestamp_us = 3'000'000u + 20'000u * k;
  raw.counts.resize(static_cast<std::size_t>(volts.size()));
  for (Eigen::Index i = 0; i < volts.size(); ++i)
    raw.counts[static_cast<std::size_t>(i)] = adc_code(sensor.adc, volts.data()[i]);
  return raw;
}

/// Counts spread over the whole ADC range (every digit of the CSV matters), 8 frames.
std::string record_ramp(const std::string& path, const Sensor& sensor, int frames = 8) {
  Recorder recorder(path, sensor);
  const int N = sensor.electrode_count();
  for (int k = 0; k < frames; ++k) {
    Frame volts(N, N);
    for (int i = 0; i < N * N; ++i)
      volts.data()[i] = adc_step_V(sensor.adc) * static_cast<double>((97 * i + 1009 * k) % (1 << sensor.adc.bits));
    recorder.record(packet_of(sensor, volts, static_cast<std::uint32_t>(k)));
  }
  recorder.close();
  return path;
}

/// The volts FileSource replays (what `emit live --source file:` saw), every frame.
std::vector<Frame> replayed(const std::string& path, const Sensor& sensor) {
  FileSource source(path, sensor, true);
  std::vector<Frame> frames;
  for (SourceFrame frame; !source.finished();) {
    source.next(frame, std::chrono::milliseconds(0));
    frames.push_back(frame.volts);
  }
  return frames;
}

// frames_csv writes %.7f: a reading comes back within half its last digit, 5e-8 V (a 12-bit step
// of 3.3 V is 0.8 mV: every count survives); the reference is the first K frames, the frames all.
TEST(ExportJob, FramesComeBackAsTheRecordingHoldsThem) {
  const std::string dir = test::temp_folder("export_job_frames");
  const Sensor sensor = default_sensor();
  ExportJob job;
  job.recording_path = record_ramp(dir + "/r.emitrec", sensor);
  job.frames_path = dir + "/f.csv";
  job.reference_path = dir + "/ref.csv";
  job.reference_frames = 3;
  const ExportReport report = run_export_job(job);
  EXPECT_EQ(report.frames, 8u);
  EXPECT_EQ(report.reference_frames, 3u);
  EXPECT_NEAR(report.board_seconds, 7 * 0.020, 1e-9);  // 8 frames 20 ms apart, µs stamps
  EXPECT_EQ(report.frames_missed, 0u);
  const std::vector<Frame> recorded = replayed(job.recording_path, sensor);
  const std::vector<Frame> frames = read_frames_csv(job.frames_path, 16),
                           reference = read_frames_csv(dir + "/ref.csv", 16);
  ASSERT_EQ(frames.size(), recorded.size());
  ASSERT_EQ(reference.size(), 3u);
  constexpr double printed_V = 5e-8;  // half of %.7f's last digit
  for (std::size_t f = 0; f < frames.size(); ++f) {
    EXPECT_LE((frames[f] - recorded[f]).cwiseAbs().maxCoeff(), printed_V) << "frame " << f;
    if (f < 3) {
      EXPECT_LE((reference[f] - recorded[f]).cwiseAbs().maxCoeff(), printed_V) << "frame " << f;
    }
  }
  EXPECT_GT(recorded[7].maxCoeff(), 3.0);  // the ramp reaches the top of the 3.3 V range
  EXPECT_FALSE(fs::exists(dir + "/f.csv.partial"));

  // Frames the run lost (numbers 3 and 4 missing) are counted, as `emit live` counts them; a board
  // restart (a number behind the last) is no gap.
  {
    Recorder recorder(dir + "/gaps.emitrec", sensor);
    for (const std::uint32_t k : {0u, 1u, 2u, 5u, 6u, 0u, 1u}) recorder.record(packet_of(sensor, recorded[0], k));
    recorder.close();
  }
  job.recording_path = dir + "/gaps.emitrec";
  job.reference_path.clear();
  EXPECT_EQ(run_export_job(job).frames_missed, 2u);
}

// A crashed run's recording, cut 100 bytes into its 9th packet: its 8 whole frames exported to
// f.csv.partial, the error names the cut and the kept file, and f.csv (a good earlier export) is
// not replaced.
TEST(ExportJob, ACutRecordingExportsItsWholeFramesThenFails) {
  const std::string dir = test::temp_folder("export_job_cut");
  const Sensor sensor = default_sensor();
  const std::string rec = record_ramp(dir + "/r.emitrec", sensor, 9);
  fs::resize_file(rec, 32 + 8 * 532 + 100);
  std::ofstream(dir + "/f.csv") << "good\n";
  ExportJob job;
  job.recording_path = rec;
  job.frames_path = dir + "/f.csv";
  const std::string error = test::error_of([&] { run_export_job(job); });
  EXPECT_NE(error.find("r.emitrec: truncated: frame 8 (byte 4288) has 100 of its 532 bytes"), std::string::npos)
      << error;
  EXPECT_NE(error.find("the 8 frames before it exported to " + dir + "/f.csv.partial"), std::string::npos) << error;
  EXPECT_EQ(test::read_text(dir + "/f.csv"), "good\n");
  EXPECT_EQ(read_frames_csv(dir + "/f.csv.partial", 16).size(), 8u);
}

// What is not a recording, is missing, or asks for nothing: one line naming it, nothing written.
TEST(ExportJob, RefusesWhatIsNotARecordingWritingNothing) {
  const std::string dir = test::temp_folder("export_job_bad");
  const Sensor sensor = default_sensor();
  ExportJob job;
  job.frames_path = dir + "/f.csv";
  job.recording_path = dir + "/missing.emitrec";
  EXPECT_EQ(test::error_of([&] { run_export_job(job); }), dir + "/missing.emitrec: cannot open the recording");
  std::ofstream(dir + "/frames.csv") << std::string(600, '1') << "\n";  // a frames CSV given by mistake
  job.recording_path = dir + "/frames.csv";
  EXPECT_NE(test::error_of([&] { run_export_job(job); }).find(dir + "/frames.csv: not an emit recording"),
            std::string::npos);
  job.recording_path = record_ramp(dir + "/empty.emitrec", sensor, 0);  // a run stopped before its first frame
  EXPECT_EQ(test::error_of([&] { run_export_job(job); }),
            dir + "/empty.emitrec: no frames to export (an empty recording)");
  fs::resize_file(job.recording_path, 32 + 300);  // only a cut packet
  EXPECT_EQ(test::error_of([&] { run_export_job(job); }),
            dir + "/empty.emitrec: no frames to export (" + dir +
                "/empty.emitrec: truncated: frame 0 (byte 32) has 300 of its 532 bytes)");
  job.recording_path = record_ramp(dir + "/r.emitrec", sensor, 2);
  job.frames_path.clear();
  EXPECT_EQ(test::error_of([&] { run_export_job(job); }),
            "nothing to export: give --frames, --reference, --contacts, --tracks or --mcap");
  job.reference_path = dir + "/ref.csv";  // 2 frames, fewer than the reference's 10
  EXPECT_EQ(test::error_of([&] { run_export_job(job); }),
            dir + "/r.emitrec: 2 frames, fewer than the reference's 10 (--reference-frames)");
  job.reference_path = dir + "/r.emitrec";  // an output over the input
  EXPECT_NE(test::error_of([&] { run_export_job(job); }).find("writing it would destroy the input"), std::string::npos);
  EXPECT_EQ(fs::file_size(dir + "/r.emitrec"), 32u + 2u * 532u);
  for (const auto& entry : fs::directory_iterator(dir))
    EXPECT_TRUE(entry.path().extension() == ".emitrec" || entry.path().filename() == "frames.csv") << entry.path();
}

// A recording of the twin (10 untouched frames, then presses across the sheet, ADC noise on)
// exported with contacts by contact fitting: each press found once, within 0.5 mm of the twin's
// place (README's accuracy table: fit's p95 is 0.13 mm on this sheet, twin and reconstruction on
// different meshes; measured here 0.01 to 0.10 mm, 2026-11-28; 0.5 mm is about 4 times the p95,
// and far below the paper method's 3.5 mm mean), on the
// board's clock. The same contacts as `emit reconstruct` gives on the exported reference and
// frames (its frame f at f / 50 s, the board's 3 s later: the lines differ in board_time_s only).
TEST(ExportJob, ContactsAreTheReconstructJobsOnTheExportedFilesWithBoardTimes) {
  const std::string dir = test::temp_folder("export_job_contacts");
  const Sensor sensor = default_sensor();
  Twin twin(sensor);
  const std::vector<Press> presses = {{15, 15, 5, 10}, {30, 30, 5, 6}, {45, 20, 5, 12}, {22, 44, 5, 8}};
  {
    Recorder recorder(dir + "/r.emitrec", sensor);
    std::uint32_t k = 0;
    for (; k < 10; ++k) recorder.record(packet_of(sensor, twin.frame({}), k));
    for (const Press& press : presses)
      for (int repeat = 0; repeat < 2; ++repeat) recorder.record(packet_of(sensor, twin.frame({press}), k++));
    recorder.close();
  }
  ExportJob job;
  job.recording_path = dir + "/r.emitrec";
  job.frames_path = dir + "/f.csv";
  job.reference_path = dir + "/ref.csv";
  job.contacts_path = dir + "/c.jsonl";
  job.mcap_path = dir + "/c.mcap";
  job.cache_dir = dir;
  const ExportReport report = run_export_job(job);
  EXPECT_EQ(report.frames, 18u);
  EXPECT_EQ(report.reference_frames, 10u);
  EXPECT_TRUE(report.dead_electrodes.empty());
  EXPECT_FALSE(report.calibrated);

  std::istringstream lines(test::read_text(dir + "/c.jsonl"));
  std::vector<ContactsLine> exported;
  for (std::string line; std::getline(lines, line);) exported.push_back(parse_contacts_record(line));
  ASSERT_EQ(exported.size(), 18u);
  for (std::size_t f = 0; f < exported.size(); ++f) {
    const ContactsLine& line = exported[f];
    EXPECT_EQ(line.frame, static_cast<long>(f));
    EXPECT_NEAR(line.times.board_s, 3.0 + 0.02 * static_cast<double>(f), 1e-9);  // the packets' µs stamps
    EXPECT_TRUE(std::isnan(line.times.host_unix_s));                             // a recording does not hold it
    if (f < 10) {
      EXPECT_TRUE(line.contacts.empty()) << "untouched frame " << f;
      continue;
    }
    const Press& press = presses[(f - 10) / 2];
    ASSERT_EQ(line.contacts.size(), 1u) << "frame " << f;
    EXPECT_LT(std::hypot(line.contacts[0].x_mm - press.x_mm, line.contacts[0].y_mm - press.y_mm), 0.5) << "frame " << f;
  }

  ReconstructJob again;
  again.reference_path = dir + "/ref.csv";
  again.frames_path = dir + "/f.csv";
  again.contacts_path = dir + "/again.jsonl";
  again.cache_dir = dir;
  run_reconstruct_job(again);
  std::istringstream again_lines(test::read_text(dir + "/again.jsonl"));
  std::size_t f = 0;
  for (std::string line; std::getline(again_lines, line); ++f) {
    ASSERT_LT(f, exported.size());
    const ContactsLine read = parse_contacts_record(line);
    ASSERT_EQ(read.contacts.size(), exported[f].contacts.size()) << "frame " << f;
    for (std::size_t c = 0; c < read.contacts.size(); ++c) {
      EXPECT_EQ(read.contacts[c].x_mm, exported[f].contacts[c].x_mm) << "frame " << f;
      EXPECT_EQ(read.contacts[c].force_N, exported[f].contacts[c].force_N) << "frame " << f;
      EXPECT_EQ(read.contacts[c].id, exported[f].contacts[c].id) << "frame " << f;
    }
  }
  EXPECT_EQ(f, exported.size());
  const std::string mcap = test::read_text(dir + "/c.mcap");
  EXPECT_EQ(mcap.substr(1, 4), "MCAP");  // the magic: a whole file renamed into place
  EXPECT_FALSE(fs::exists(dir + "/c.mcap.partial"));
}

}  // namespace
}  // namespace emit
