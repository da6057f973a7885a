#include "emit/jobs/demo_job.hpp"

#include <chrono>
#include <filesystem>

#include "emit/core/output_file.hpp"
#include "emit/io/calibration_json.hpp"
#include "emit/io/contacts_jsonl.hpp"
#include "emit/io/frames_csv.hpp"
#include "emit/io/presses_csv.hpp"
#include "emit/pipeline/pipeline.hpp"
#include "emit/pipeline/press_calibration.hpp"
#include "emit/render/pressure_map.hpp"
#include "emit/sensor/sensor_json.hpp"
#include "emit/twin/press_scripts.hpp"
#include "emit/twin/twin.hpp"

namespace emit {

namespace {

double seconds_since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

}  // namespace

DemoReport run_demo_reconstruction(const std::string& out_dir, const std::string& cache_dir, const Progress& progress) {
  std::filesystem::create_directories(out_dir);
  DemoReport report;
  report.sensor = default_sensor();
  const Sensor& sensor = report.sensor;
  report.presses = {
      {{30, 30, 5, 10}},                  // centre, 5 mm indenter, 10 N
      {{12, 48, 5, 5}},                   // near the top-left corner, lighter
      {{20, 20, 4, 8}, {42, 40, 6, 15}},  // two fingers
      {{45, 15, 3, 2}},                   // a small, light press
  };
  auto start = std::chrono::steady_clock::now();
  progress.say("the twin records a reference, 20 presses of known force and the frames to reconstruct");
  Twin twin(sensor);
  const Reference reference{twin.frame({}), 1};  // one untouched frame
  PressStyle style;                              // 5 mm indenter, 2 to 39 N: 0.025 to 0.5 N/mm², the paper's range
  style.min_force_N = 2, style.max_force_N = 39, style.seed = 11;
  const PressSequence calibration_presses = random_script(sensor, 20, style);
  std::vector<Frame> calibration_frames, frames;
  for (const auto& presses : calibration_presses) calibration_frames.push_back(twin.frame(presses));
  for (const auto& presses : report.presses) frames.push_back(twin.frame(presses));
  report.calibration_presses = calibration_presses.size();
  report.twin_seconds = seconds_since(start);

  start = std::chrono::steady_clock::now();
  PressCalibrationOptions calibrate;  // contact fitting on the nominal sheet (the twin's is uniform)
  calibrate.fit_sheet = false;
  calibrate.cache_dir = cache_dir;
  report.calibration = std::get<FitCalibration>(
      calibrate_from_presses(sensor, calibrate, reference, calibration_frames, calibration_presses, progress.stage)
          .calibration);
  Pipeline fitting(sensor, {Method::fit, 0, cache_dir, {}}, report.calibration, progress.stage);
  Pipeline paper(sensor, {Method::paper, 0, cache_dir, {}}, std::nullopt, progress.stage);
  report.model_seconds = seconds_since(start);
  report.triangles = static_cast<long>(paper.model().mesh.triangle_count());
  report.fit_mesh_nodes = static_cast<long>(fitting.fit_mesh()->node_count());

  Reconstructor fit_reconstructor = fitting.reconstructor();
  Reconstructor paper_reconstructor = paper.reconstructor();
  fit_reconstructor.set_reference(reference);
  paper_reconstructor.set_reference(reference);
  OutputFile contacts_file({"", out_dir + "/contacts.jsonl"});
  for (std::size_t f = 0; f < frames.size(); ++f) {
    report.fitted.push_back(fit_reconstructor.process(frames[f]));
    report.paper.push_back(paper_reconstructor.process(frames[f]));
    write_contacts_line(contacts_file.stream(), static_cast<long>(f), report.fitted.back(),
                        1e3 * fit_reconstructor.fit_result()->rms_misfit_V);
    std::vector<Circle> outlines;
    for (const Press& p : report.presses[f]) outlines.push_back({Vector2(p.x_mm, p.y_mm), p.radius_mm, p.z_mm});
    write_pressure_map(fit_reconstructor.mesh(), fit_reconstructor.pressure(), outlines,
                       "frame " + std::to_string(f) + ": pressure by contact fitting (circles: the true presses)",
                       out_dir + "/" + frame_image_name(f));
  }
  contacts_file.commit();
  write_frames_csv(out_dir + "/frames.csv", frames);
  write_presses_csv(out_dir + "/presses.csv", report.presses);
  report.calibration_path = out_dir + "/calibration.json";
  write_calibration(report.calibration_path, report.calibration);
  return report;
}

}  // namespace emit
