// `emit calibrate --capture` (jobs/capture_job.hpp, issue 33): a scripted person on the twin
// (sim:calibration, twin/calibration_person.hpp) stands in for someone at the board; the capture
// finds each press, places the fingers roughly, labels the weights, writes files a calibration
// reads, and keeps them when stopped.
#include "emit/jobs/capture_job.hpp"

#include <cmath>
#include <string>

#include <gtest/gtest.h>

#include "emit/core/errors.hpp"
#include "emit/io/calibration_json.hpp"
#include "emit/io/frames_csv.hpp"
#include "emit/io/presses_csv.hpp"
#include "emit/pipeline/pipeline.hpp"
#include "emit/sensor/sensor_json.hpp"
#include "emit/twin/calibration_person.hpp"
#include "emit/twin/press_scripts.hpp"
#include "emit/twin/twin.hpp"
#include "test_support.hpp"

namespace emit {
namespace {

/// A capture from sim:calibration:PRESSES on the 30 mm sheet, unpaced, without the calibration.
CaptureJob small_capture(const std::string& dir, int presses) {
  CaptureJob job;
  job.source_spec = "sim:calibration:" + std::to_string(presses);
  job.source.frames_per_s = 0;  // as fast as the twin goes; the person keeps its 50 frames/s clock
  job.calibrate.sensor_path = test::source_path("examples/sensors/square30.json");
  job.calibrate.out_path = dir + "/calibration.json";
  job.presses = presses;
  job.run_calibration = false;
  return job;
}

TEST(CaptureJob, FindsEveryPressPlacesTheFingersAndLabelsTheWeights) {
  const std::string dir = test::temp_folder("capture_job");
  const CaptureJob job = small_capture(dir, 3);
  std::vector<std::string> lines;
  CaptureSay say;
  say.line = [&](const std::string& text) { lines.push_back(text); };
  const std::atomic<bool> stop{false};
  const CaptureReport report = run_capture_job(job, stop, say);
  EXPECT_FALSE(report.stopped);
  EXPECT_EQ(report.ended, "");
  EXPECT_EQ(report.capture_dir, dir + "/calibration_capture");
  EXPECT_EQ(report.finger_presses, 3);
  EXPECT_EQ(report.weights, 2);
  // The files: the quiet frames; a frame per press; the presses, places unknown, the fingers'
  // forces unknown, the weights' known.
  const Sensor sensor = load_sensor(job.calibrate.sensor_path);
  EXPECT_EQ(read_frames_csv(report.reference_path, 16).size(), 25u);
  EXPECT_EQ(read_frames_csv(report.frames_path, 16).size(), 5u);
  const PressSequence presses = read_presses_csv(report.truth_path, 5, UnknownPresses::allowed);
  ASSERT_EQ(presses.size(), 5u);
  for (std::size_t f = 0; f < presses.size(); ++f) {
    ASSERT_EQ(presses[f].size(), 1u);
    EXPECT_FALSE(place_known(presses[f][0]));
    EXPECT_EQ(force_known(presses[f][0]), f >= 3);
  }
  EXPECT_EQ(presses[3][0].force_N, 2.0);
  EXPECT_EQ(presses[4][0].force_N, 5.0);
  // The nominal fit places each finger where the person pressed: the twin's sheet is the
  // nominal one here (no realistic departures), so within the fit's error on a different mesh,
  // well under a millimetre (README: contact fitting's position error on the twin); the map's
  // cells are 5 mm.
  CalibrationPersonOptions person_options;
  person_options.presses = 3;
  person_options.seed = job.source.seed;
  const CalibrationPerson person(sensor, person_options);
  ASSERT_EQ(report.placed_mm.size(), 3u);
  for (std::size_t i = 0; i < 3; ++i) {
    const Press& truth = person.presses()[i].press;
    EXPECT_NEAR(report.placed_mm[i].x(), truth.x_mm, 1.0) << "press " << i;
    EXPECT_NEAR(report.placed_mm[i].y(), truth.y_mm, 1.0) << "press " << i;
  }
  EXPECT_GE(report.cells_covered, 1);
  EXPECT_LE(report.cells_covered, 3);
  EXPECT_EQ(report.cells, 36);  // 6 × 6, all on a square sheet
  // Told, one line a step: the reference's noise, each press, each weight.
  const auto said = [&](const std::string& text) {
    for (const std::string& l : lines)
      if (l.find(text) != std::string::npos) return true;
    return false;
  };
  EXPECT_TRUE(said("1. Lift everything off the sheet"));
  EXPECT_TRUE(said("a reading's noise"));
  EXPECT_TRUE(said("press 3 of 3: near ("));
  EXPECT_TRUE(said("3. Put the 5.00 N weight down anywhere, then lift it"));
}

// Ctrl-C (the stop flag) after the first press: the files hold the reference and that press,
// complete, and the run says how to calibrate from them offline.
TEST(CaptureJob, StoppedKeepsCompleteFilesAndSaysHowToGoOn) {
  const std::string dir = test::temp_folder("capture_job_stop");
  const CaptureJob job = small_capture(dir, 3);
  std::atomic<bool> stop{false};
  std::string last;
  CaptureSay say;
  say.line = [&](const std::string& text) {
    last = text;
    if (text.rfind("press 1 of 3", 0) == 0) stop = true;
  };
  const CaptureReport report = run_capture_job(job, stop, say);
  EXPECT_TRUE(report.stopped);
  EXPECT_EQ(report.finger_presses, 1);
  EXPECT_EQ(read_frames_csv(report.frames_path, 16).size(), 1u);
  EXPECT_EQ(read_presses_csv(report.truth_path, 1, UnknownPresses::allowed).size(), 1u);
  EXPECT_EQ(read_frames_csv(report.reference_path, 16).size(), 25u);
  EXPECT_EQ(last, "stopped at press 2: kept the reference and 1 finger presses, 0 weights in " + report.capture_dir +
                      "; calibrate from them with: " + report.offline_command);
  EXPECT_EQ(report.offline_command, "emit calibrate --sensor " + job.calibrate.sensor_path + " --reference " +
                                        report.reference_path + " --frames " + report.frames_path + " --truth " +
                                        report.truth_path + " --out " + job.calibrate.out_path);
  CaptureJob bad = job;
  bad.calibrate.out_path.clear();
  EXPECT_EQ(test::error_of([&] { run_capture_job(bad, stop, {}); }), "--capture needs --out, the calibration to write");
}

// Issue 33's end-to-end round, small: a scripted person presses 12 times anywhere and puts two
// weights down; the capture's calibration (the sheet's field quadratic and the drive: a twin of
// the nominal sheet has no series resistance or moved electrode to find) then places held-out
// presses within 0.5 mm on average (the target; the full round, presses on a realistic
// sheet with everything fitted, is `emit eval --realistic --unplaced 5`). In the slow suites:
// twin frames and a calibration of 14 presses.
TEST(CaptureEndToEnd, SimPersonCaptureCalibrationPlacesHeldOutPressesWithinHalfAMillimetre) {
  const std::string dir = test::temp_folder("capture_end_to_end");
  CaptureJob job;
  job.source_spec = "sim:calibration:12";  // 12 presses, 2 N and 5 N weights
  job.presses = 12;
  job.source.frames_per_s = 0;
  job.calibrate.out_path = dir + "/calibration.json";
  job.calibrate.options.sensor.sheet_terms = SheetCorrection::quadratic_terms;
  job.calibrate.options.sensor.fit_series_resistance = job.calibrate.options.sensor.fit_electrode_positions = false;
  const CaptureReport report = run_capture_job(job, std::atomic<bool>{false}, {});
  ASSERT_TRUE(report.calibration && report.calibration->presses);
  EXPECT_EQ(report.finger_presses, 12);
  EXPECT_EQ(report.weights, 2);
  // Held-out presses on the same sheet, reconstructed with the capture's calibration.
  const Sensor sensor = default_sensor();
  const Pipeline pipeline(sensor, PipelineOptions{Method::fit, 0, "", {}}, load_calibration(job.calibrate.out_path));
  Reconstructor reconstructor = pipeline.reconstructor();
  reconstructor.set_reference(average_reference(read_frames_csv(report.reference_path, 16)));
  Twin twin(sensor);
  PressScript held_out;
  held_out.kind = PressScript::Kind::random;
  held_out.frames = 20;
  held_out.style.min_force_N = 2, held_out.style.max_force_N = 39, held_out.style.seed = 99;
  double sum_mm = 0;
  int found = 0;
  for (const auto& presses : run_script(sensor, held_out)) {
    const auto& contacts = reconstructor.process(twin.frame(presses));
    if (contacts.empty()) continue;
    ++found;
    sum_mm += std::hypot(contacts[0].x_mm - presses[0].x_mm, contacts[0].y_mm - presses[0].y_mm);
  }
  EXPECT_EQ(found, 20);
  EXPECT_LE(sum_mm / found, 0.5);  // issue 33's target: position after calibration ≤ 0.5 mm mean
}

}  // namespace
}  // namespace emit
