#include "emit/jobs/simulate_job.hpp"
#include "emit/mesh/sheet_file.hpp"

#include <cstdio>
#include <filesystem>

#include <nlohmann/json.hpp>

#include "emit/core/errors.hpp"
#include "emit/core/limits.hpp"
#include "emit/core/output_paths.hpp"
#include "emit/io/frames_csv.hpp"
#include "emit/io/presses_csv.hpp"
#include "emit/pipeline/pipeline.hpp"
#include "emit/render/field_image.hpp"
#include "emit/render/image.hpp"
#include "emit/render/pressure_map.hpp"
#include "emit/sensor/sensor_json.hpp"
#include "emit/sensor/surface.hpp"

namespace emit {

namespace {

/// The default path of a file written beside --out: none beside a device or FIFO (it would be
/// made in /dev, say).
std::string beside_out(const std::string& out_path, const std::string& suffix, const std::string& remedy) {
  if (output_kind(out_path) != OutputKind::file)
    throw InvalidInput("--out " + out_path + " is not a regular file: " + remedy);
  std::filesystem::path p(out_path);
  return (p.parent_path() / (p.stem().string() + suffix)).string();
}

/// What a realistic sheet drew, for checking a calibration against the truth.
void write_sheet_json(std::ostream& out, const Sensor& nominal, const RealisticSheet& sheet,
                      const RealisticSheetOptions& options) {
  nlohmann::json j;
  j["seed"] = options.seed;
  j["options"] = {{"sheet_scale", options.sheet_scale},
                  {"field", options.field},
                  {"shift_mm", options.electrode_shift_mm},
                  {"series_ohm", options.series_resistance_ohm},
                  {"drive_V", {options.drive_voltage_low_V, options.drive_voltage_high_V}},
                  {"blur_mm", options.blur_mm}};
  j["sheet_scale"] = sheet.sheet_scale;
  j["sheet_resistance_ohm_per_sq"] = sheet.twin_sensor.sheet_resistance_ohm_per_sq;
  j["nominal_sheet_resistance_ohm_per_sq"] = nominal.sheet_resistance_ohm_per_sq;
  j["field_factor_range"] = {sheet.field_min_factor, sheet.field_max_factor};
  j["drive_voltage_V"] = sheet.drive_voltage_V;
  j["blur_mm"] = sheet.blur_mm;
  j["electrode_shift_mm"] = sheet.shift_mm;
  j["series_resistance_ohm"] = sheet.series_ohm;
  out << j.dump(2) << '\n';
}

void write_potential_images(Twin& twin, const PressSequence& sequence, const std::string& dir) {
  for (std::size_t f = 0; f < sequence.size(); ++f) {
    std::vector<Circle> outlines;
    for (const Press& p : sequence[f]) outlines.push_back({Vector2(p.x_mm, p.y_mm), p.radius_mm, p.z_mm});
    FieldImageOptions image;
    image.title = "frame " + std::to_string(f) + ": probing-layer potential, electrode 0 grounded";
    write_png(render_sheet_field(twin.mesh(), twin.potentials(sequence[f]).col(0), outlines, image),
              dir + "/" + frame_image_name(f));
  }
}

/// The script's frames within what a run holds (core/limits.hpp), before any is made.
void check_script_size(const Sensor& sensor, const PressScript& script, int electrodes) {
  const double frames = script_frame_count(sensor, script);
  if (script.kind != PressScript::Kind::grid)
    return limits::check_frames_held("--frames " + std::to_string(script.frames), frames, electrodes,
                                     "simulate them in several runs (--seed)");
  char what[96];
  std::snprintf(what, sizeof what, "--spacing-mm %g (a grid over the sheet)", script.spacing_mm);
  limits::check_frames_held(what, frames, electrodes, "give a larger spacing");
}

}  // namespace

SimulateReport run_simulate_job(const SimulateJob& job, const Progress& progress) {
  SimulateReport report;
  report.sensor = load_sheet_sensor(job.sensor_path);
  require_emit_protocol(report.sensor, job.sensor_path);
  Sensor& sensor = report.sensor;
  if (job.noise_V >= 0) sensor.adc.noise_V = job.noise_V;
  if (!job.presses.empty() && job.script) throw InvalidInput("give --press or --script, not both");
  if (job.presses.empty() && !job.script)
    throw InvalidInput("nothing to simulate: give --press x,y,r,F or --script NAME");
  const int N = electrode_count_of(sensor);
  if (job.script) check_script_size(sensor, *job.script, N);
  report.presses = job.script ? run_script(sensor, *job.script) : PressSequence{job.presses};
  for (std::size_t f = 0; f < report.presses.size(); ++f)
    for (std::size_t i = 0; i < report.presses[f].size(); ++i) {
      Press& press = report.presses[f][i];
      validate_press(sensor, press, "frame " + std::to_string(f) + ", press " + std::to_string(i));
      // Where the twin centres it: on a curved sheet the truth file says so (a z_mm column).
      const Vector3 point = surface_point_mm(sensor.shape, press_chart_mm(sensor.shape, press));
      press.x_mm = point.x(), press.y_mm = point.y(), press.z_mm = point.z();
    }
  report.truth_path = job.truth_path.empty() ? beside_out(job.out_path, "_presses.csv",
                                                          "give --truth too (by default the presses go beside --out)")
                                             : job.truth_path;
  if (job.realistic) {
    job.realistic->validate();
    report.sheet_path = job.sheet_path.empty()
                            ? beside_out(job.out_path, "_sheet.json",
                                         "with --realistic it must be a file (the sheet's description goes beside it)")
                            : job.sheet_path;
  }
  auto outputs = open_outputs({{"--sensor", job.sensor_path}, {"--sensor's mesh file", sensor.shape.mesh_path}},
                              {OutputRequest{{"--out", job.out_path}}, OutputRequest{{"--truth", report.truth_path}},
                               OutputRequest{{"the realistic sheet's description", report.sheet_path}}});
  auto& [out, truth, sheet_json] = outputs;
  if (job.twin.dead_electrode >= N)
    throw InvalidInput("--dead-electrode " + std::to_string(job.twin.dead_electrode) + ": the sensor has " +
                       std::to_string(N) + " electrodes, 0 to " + std::to_string(N - 1));
  prepare_output_folder({"--images", job.images_dir});

  Sensor twin_sensor = sensor;
  TwinOptions twin_options = job.twin;
  if (job.realistic) {
    report.realistic = make_realistic_sheet(sensor, *job.realistic, job.twin);
    twin_sensor = report.realistic->twin_sensor;
    twin_options = report.realistic->twin_options;
  }
  progress.say("meshing the twin of " + sensor.name);
  Twin twin(twin_sensor, twin_options);
  report.twin_mesh = measure_mesh_quality(twin.mesh());
  for (std::size_t f = 0; f < report.presses.size(); ++f) {
    report.frames.push_back(twin.frame(report.presses[f]));
    progress.step("simulating frame", static_cast<long>(f + 1), static_cast<long>(report.presses.size()));
  }
  write_frames_csv(out.stream(), report.frames);
  write_presses_csv(truth.stream(), report.presses);
  if (report.realistic) write_sheet_json(sheet_json.stream(), sensor, *report.realistic, *job.realistic);
  commit_outputs(outputs);
  if (!job.images_dir.empty()) write_potential_images(twin, report.presses, job.images_dir);
  return report;
}

}  // namespace emit
