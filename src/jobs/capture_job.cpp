#include "emit/jobs/capture_job.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <limits>

#include "emit/core/errors.hpp"
#include "emit/core/option_check.hpp"
#include "emit/core/output_paths.hpp"
#include "emit/frame/reconstructor.hpp"
#include "emit/frame/reference.hpp"
#include "emit/io/frames_csv.hpp"
#include "emit/io/presses_csv.hpp"
#include "emit/live/open_source.hpp"
#include "emit/mesh/sheet_file.hpp"
#include "emit/pipeline/pipeline.hpp"
#include "emit/sensor/adc.hpp"
#include "emit/sensor/surface.hpp"
#include "emit/twin/sim_script.hpp"

namespace emit {

void CaptureJob::validate() const {
  const char* owner = "CaptureJob";
  option_check::at_least(owner, "quiet_frames", quiet_frames, 2);
  option_check::at_least(owner, "presses", presses, 1);
  option_check::at_least(owner, "coverage_cells", coverage_cells, 1);
  option_check::positive(owner, "finger_radius_mm", finger_radius_mm);
  option_check::positive(owner, "weight_radius_mm", weight_radius_mm);
  for (const double weight : weights_N) option_check::positive(owner, "weights_N", weight);
  option_check::positive(owner, "source_timeout_s", source_timeout_s);
  source.validate();
  segmenter.validate();
}

namespace {

std::string format(const char* pattern, double a, double b = 0, double c = 0) {
  char text[256];
  std::snprintf(text, sizeof text, pattern, a, b, c);
  return text;
}

/// The sheet in coverage_cells × coverage_cells cells over its outline's box (less a finger's
/// radius): which are on the sheet (their centre inside it) and which a press has been placed in.
class CoverageMap {
 public:
  /// The cells cover the box where a finger's centre can be: the sheet's, less `inset_mm` (the
  /// finger's radius) on every side.
  CoverageMap(const Sensor& sensor, int cells, double inset_mm) : cells_(cells), outline_(sheet_outline(sensor)) {
    for (int k = 0; k < 512; ++k) box_.extend(outline_.point_at(outline_.length_mm() * k / 512));
    const Vector2 inset = Vector2::Constant(std::min(inset_mm, 0.25 * box_.sizes().minCoeff()));
    box_ = Eigen::AlignedBox2d(box_.min() + inset, box_.max() - inset);
    on_sheet_.resize(index(0, cells));
    covered_.assign(on_sheet_.size(), false);
    for (int j = 0; j < cells; ++j)
      for (int i = 0; i < cells; ++i) on_sheet_[index(i, j)] = outline_.contains(cell_centre(i, j));
  }
  /// Marks the cell of chart point p; whether it was newly covered.
  bool mark(const Vector2& p) {
    const Vector2 at = (p - box_.min()).cwiseQuotient(box_.sizes()) * cells_;
    const int i = std::clamp(static_cast<int>(std::floor(at.x())), 0, cells_ - 1);
    const int j = std::clamp(static_cast<int>(std::floor(at.y())), 0, cells_ - 1);
    const auto k = index(i, j);
    if (!on_sheet_[k] || covered_[k]) return false;
    covered_[k] = true;
    return true;
  }
  int cells() const { return static_cast<int>(std::count(on_sheet_.begin(), on_sheet_.end(), true)); }
  int covered() const { return static_cast<int>(std::count(covered_.begin(), covered_.end(), true)); }
  /// Rows from the top (high y): '#' covered, '.' not yet, ' ' off the sheet.
  std::string text() const {
    std::string map;
    for (int j = cells_ - 1; j >= 0; --j) {
      map += "    ";
      for (int i = 0; i < cells_; ++i) {
        const auto k = index(i, j);
        map += on_sheet_[k] ? (covered_[k] ? "# " : ". ") : "  ";
      }
      map += '\n';
    }
    return map;
  }

 private:
  std::size_t index(int i, int j) const {
    return static_cast<std::size_t>(j) * static_cast<std::size_t>(cells_) + static_cast<std::size_t>(i);
  }
  Vector2 cell_centre(int i, int j) const {
    return box_.min() + Vector2((i + 0.5) * box_.sizes().x() / cells_, (j + 0.5) * box_.sizes().y() / cells_);
  }
  int cells_;
  const Border& outline_;
  Eigen::AlignedBox2d box_;
  std::vector<bool> on_sheet_, covered_;
};

std::string default_capture_dir(const std::string& out_path) {
  std::string stem = out_path;
  if (stem.size() > 5 && stem.compare(stem.size() - 5, 5, ".json") == 0) stem.erase(stem.size() - 5);
  return stem + "_capture";
}

}  // namespace

CaptureReport run_capture_job(const CaptureJob& job, const std::atomic<bool>& stop, const CaptureSay& say,
                              const Progress& progress) {
  job.validate();
  const auto line = [&](const std::string& text) {
    if (say.line) say.line(text);
  };
  const auto status = [&](const std::string& text) {
    if (say.status) say.status(text);
  };
  if (job.calibrate.out_path.empty()) throw InvalidInput("--capture needs --out, the calibration to write");
  CaptureReport report;
  report.capture_dir = job.capture_dir.empty() ? default_capture_dir(job.calibrate.out_path) : job.capture_dir;
  report.reference_path = report.capture_dir + "/reference.csv";
  report.frames_path = report.capture_dir + "/frames.csv";
  report.truth_path = report.capture_dir + "/presses.csv";
  {  // --out and the capture's files can be written (checked now, not after minutes of pressing)
    prepare_output_folder({"--capture-dir", report.capture_dir});
    auto outputs = open_outputs({{"--sensor", job.calibrate.sensor_path}},
                                {OutputRequest{{"--out", job.calibrate.out_path}},
                                 OutputRequest{{"--capture-dir's reference.csv", report.reference_path}},
                                 OutputRequest{{"--capture-dir's frames.csv", report.frames_path}},
                                 OutputRequest{{"--capture-dir's presses.csv", report.truth_path}}});
    (void)outputs;  // not committed: nothing is written yet
  }
  report.offline_command = "emit calibrate" +
                           (job.calibrate.sensor_path.empty() ? "" : " --sensor " + job.calibrate.sensor_path) +
                           " --reference " + report.reference_path + " --frames " + report.frames_path + " --truth " +
                           report.truth_path + " --out " + job.calibrate.out_path;
  const Sensor sensor = load_sheet_sensor(job.calibrate.sensor_path);
  require_emit_protocol(sensor, job.calibrate.sensor_path.empty() ? "the built-in sensor" : job.calibrate.sensor_path);
  // The twin (sim:…) stays untouched for the reference's frames and a few more whatever its pace:
  // its script's quiet second is fewer frames than step 1 reads when a slow machine lowers the pace.
  SourceOptions source_options = job.source;
  source_options.untouched_frames = std::max(source_options.untouched_frames, job.quiet_frames + 5);
  const std::unique_ptr<FrameSource> source = open_source(job.source_spec, sensor, source_options);
  line("source: " + source->description());
  progress.say("preparing the nominal contact fit for the coverage map");
  const Pipeline pipeline(sensor, PipelineOptions{Method::fit, 0, job.calibrate.options.cache_dir, {}}, {},
                          progress.stage);
  Reconstructor placer = pipeline.reconstructor();
  CoverageMap coverage(sensor, job.coverage_cells, job.finger_radius_mm);
  report.cells = coverage.cells();

  // The next frame, or false when stopped or the source is gone (report.ended says why).
  SourceFrame frame;
  std::uint64_t frames_read = 0;
  const auto next_frame = [&]() -> bool {
    const auto last = std::chrono::steady_clock::now();
    while (!stop) {
      if (source->finished()) {
        report.ended = "the source ended after " + std::to_string(frames_read) + " frames";
        return false;
      }
      try {
        if (source->next(frame, std::chrono::milliseconds(100))) {
          ++frames_read;
          return true;
        }
      } catch (const Error& e) {
        report.ended = e.what();
        return false;
      }
      if (std::chrono::steady_clock::now() - last > std::chrono::duration<double>(job.source_timeout_s)) {
        report.ended = "no frame from the source for " + format("%g s", job.source_timeout_s);
        return false;
      }
    }
    report.stopped = true;
    return false;
  };
  const auto finish_early = [&](const std::string& during) {
    const std::string why = report.stopped ? "stopped" : report.ended;
    if (report.noise_V == 0) {
      line(why + " " + during + ": nothing captured yet");
      return report;
    }
    if (report.finger_presses + report.weights == 0) {
      line(why + " " + during + ": kept the reference, " + report.reference_path + "; no press yet");
      return report;
    }
    line(why + " " + during + ": kept the reference and " + std::to_string(report.finger_presses) +
         " finger presses, " + std::to_string(report.weights) + " weights in " + report.capture_dir +
         "; calibrate from them with: " + report.offline_command);
    return report;
  };

  // 1. The reference and the noise.
  line("1. Lift everything off the sheet");
  std::vector<Frame> quiet;
  while (static_cast<int>(quiet.size()) < job.quiet_frames) {
    if (!next_frame()) return finish_early("while measuring the reference");
    quiet.push_back(frame.volts);
    status(format("reference: %.0f of %.0f frames", static_cast<double>(quiet.size()), job.quiet_frames));
  }
  const Reference reference = average_reference(quiet);
  report.measured_noise_V = measured_reading_noise_V(quiet);
  // An untouched sheet reads near 0 V, where the ADC clips half the noise: the model's σ (the
  // larger) is a pressed reading's (frame/press_segmenter.hpp).
  report.noise_V = std::max(report.measured_noise_V, reading_noise_V(sensor.adc));
  write_frames_csv(report.reference_path, quiet);
  line(format("reference: %.0f frames; a reading's noise %.3f mV rms (the ADC's model: %.3f mV)",
              static_cast<double>(quiet.size()), 1e3 * report.measured_noise_V, 1e3 * reading_noise_V(sensor.adc)));
  placer.set_reference(reference);
  PressSegmenter segmenter(reference, report.noise_V, job.segmenter);

  std::vector<Frame> frames;
  PressSequence presses;
  // The next stable press, its frame and press written; false when stopped or the source is gone.
  const auto capture_press = [&](const Press& press, const std::string& waiting) -> bool {
    bool touched = false;
    for (;;) {
      if (!next_frame()) return false;
      if (segmenter.push(frame.volts)) break;
      if (segmenter.touched() != touched) {
        touched = segmenter.touched();
        status(touched ? waiting + ": pressed, hold still" : waiting);
      }
    }
    frames.push_back(segmenter.press().frame);
    presses.push_back({press});
    write_frames_csv(report.frames_path, frames);
    write_presses_csv(report.truth_path, presses);
    return true;
  };
  const double nan = std::numeric_limits<double>::quiet_NaN();

  // 2. Fingers, anywhere. The twin's scripted person (sim:calibration) does not hear the prompts:
  // it presses its own count of fingers, then the weights, so step 2 takes exactly its count.
  int finger_presses = job.presses;
  bool until_covered = true;
  if (job.source_spec.rfind("sim:calibration", 0) == 0) {
    finger_presses = parse_sim_script(job.source_spec).person.presses;
    until_covered = false;
    line("the scripted person presses " + std::to_string(finger_presses) + " fingers, then puts the weights down");
  }
  line(format("2. Press anywhere, one finger at a time; cover the sheet (%.0f presses, or every one of the %.0f cells)",
              finger_presses, report.cells));
  while (report.finger_presses < finger_presses && (!until_covered || report.cells_covered < report.cells)) {
    if (!capture_press(Press{nan, nan, job.finger_radius_mm, nan},
                       "press " + std::to_string(report.finger_presses + 1)))
      return finish_early("at press " + std::to_string(report.finger_presses + 1));
    ++report.finger_presses;
    const std::vector<Contact>& contacts = placer.process(frames.back());
    const auto strongest = std::max_element(contacts.begin(), contacts.end(),
                                            [](const Contact& a, const Contact& b) { return a.force_N < b.force_N; });
    std::string where = "not placed (no contact fitted)";
    report.placed_mm.emplace_back(nan, nan);
    if (strongest != contacts.end()) {
      report.placed_mm.back() = {strongest->x_mm, strongest->y_mm};
      const Vector2 chart = press_chart_mm(sensor.shape, Press{strongest->x_mm, strongest->y_mm, 1, 1,
                                                               PressProfile::flat, strongest->z_mm});
      const bool fresh = coverage.mark(chart);
      where = format("near (%.0f, %.0f) mm", strongest->x_mm, strongest->y_mm) + (fresh ? ", a new cell" : "");
      report.cells_covered = coverage.covered();
      if (fresh) report.coverage_map = coverage.text();
      if (fresh) line(report.coverage_map.substr(0, report.coverage_map.size() - 1));
    }
    line("press " + std::to_string(report.finger_presses) + " of " + std::to_string(finger_presses) + ": " + where +
         "; " + std::to_string(report.cells_covered) + " of " + std::to_string(report.cells) + " cells covered");
  }
  report.coverage_map = coverage.text();

  // 3. The known weights, each anywhere.
  for (std::size_t w = 0; w < job.weights_N.size(); ++w) {
    const std::string weight = format("%.2f N", job.weights_N[w]);
    line("3. Put the " + weight + " weight down anywhere, then lift it");
    if (!capture_press(Press{nan, nan, job.weight_radius_mm, job.weights_N[w]}, "the " + weight + " weight"))
      return finish_early("waiting for the " + weight + " weight");
    ++report.weights;
    line("the " + weight + " weight: found");
  }

  // 4. The calibration.
  line("captured " + std::to_string(report.finger_presses) + " finger presses and " + std::to_string(report.weights) +
       " weights in " + report.capture_dir + " (to calibrate again offline: " + report.offline_command + ")");
  if (!job.run_calibration) return report;
  line("4. Calibrating");
  CalibrateJob calibrate = job.calibrate;
  calibrate.reference_path = report.reference_path;
  calibrate.frames_path = report.frames_path;
  calibrate.truth_path = report.truth_path;
  calibrate.contact_law_path.clear();
  report.calibration = run_calibrate_job(calibrate, progress);
  return report;
}

}  // namespace emit
