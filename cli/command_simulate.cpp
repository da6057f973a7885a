// emit simulate: frames from the digital twin, for given presses or a press script.
#include <array>
#include <cstdio>

#include "commands.hpp"
#include "emit/core/errors.hpp"
#include "emit/jobs/simulate_job.hpp"

namespace emit::cli {

namespace {

struct SimulateArgs {
  SimulateJob job;
  std::vector<std::string> presses;
  std::string script;
  PressScript script_options;
  double margin_mm = -1;
  std::vector<double> force_N{10.0}, separation_mm{12.0, 40.0}, from_mm, to_mm;
  bool exact = false, print_table = false;
};

std::array<double, 2> pair_or_single(const std::vector<double>& values, const char* option) {
  if (values.size() == 1) return {values[0], values[0]};
  if (values.size() == 2) return {values[0], values[1]};
  throw InvalidInput(std::string(option) + ": give one value or two (a range)");
}

void run_simulate(SimulateArgs a) {
  SimulateJob& job = a.job;
  for (const auto& text : a.presses) job.presses.push_back(parse_press(text));
  if (!a.script.empty()) {
    PressScript& script = job.script.emplace(a.script_options);
    script.kind = parse_script_kind(a.script);
    const auto force = pair_or_single(a.force_N, "--force-N");
    script.style.min_force_N = force[0], script.style.max_force_N = force[1];
    script.style.margin_mm = a.margin_mm >= 0 ? a.margin_mm : script.style.radius_mm;
    script.style.seed = job.twin.noise_seed;
    const auto separation = pair_or_single(a.separation_mm, "--separation-mm");
    script.min_separation_mm = separation[0], script.max_separation_mm = separation[1];
    if (script.kind == PressScript::Kind::moving) {
      if (a.from_mm.size() != 2 || a.to_mm.size() != 2)
        throw InvalidInput("--script moving needs --from X,Y and --to X,Y");
      script.from_mm = {a.from_mm[0], a.from_mm[1]}, script.to_mm = {a.to_mm[0], a.to_mm[1]};
    }
  }
  job.twin.adc = !a.exact;
  const SimulateReport r = run_simulate_job(job, stderr_progress());
  std::fprintf(stderr, "twin mesh: %lld triangles, %lld nodes, min angle %.1f deg\n",
               static_cast<long long>(r.twin_mesh.triangle_count), static_cast<long long>(r.twin_mesh.node_count),
               r.twin_mesh.min_angle_deg);
  std::printf("wrote %zu frames of %lld electrodes to %s and the presses to %s\n", r.frames.size(),
              static_cast<long long>(r.frames.empty() ? 0 : r.frames[0].rows()), job.out_path.c_str(),
              r.truth_path.c_str());
  if (a.print_table)
    for (const Frame& frame : r.frames) print_frame_table(frame);
  else print_frames_summary(r.frames, r.presses);
  if (!job.images_dir.empty()) std::printf("wrote %zu images to %s/\n", r.frames.size(), job.images_dir.c_str());
}

}  // namespace

void add_simulate_command(CLI::App& app) {
  auto a = std::make_shared<SimulateArgs>();
  SimulateJob& job = a->job;
  PressScript& script = a->script_options;
  CLI::App* cmd = app.add_subcommand("simulate", "Simulate frames with the digital twin");
  cmd->footer(
      "Examples:\n"
      "  emit simulate --press 30,30,5,10 --out frame.csv\n"
      "  emit simulate --script none --frames 10 --out reference.csv\n"
      "  emit simulate --sensor examples/sensors/square30.json --script grid --spacing-mm 5 --out grid.csv\n"
      "  emit simulate --script two-finger --frames 50 --separation-mm 12,40 --force-N 5,20 --out two.csv\n"
      "  emit simulate --script moving --from 10,10 --to 50,50 --frames 30 --out move.csv");
  cmd->add_option("--sensor", job.sensor_path, "Sensor description (JSON); default: the built-in 60 mm sensor")
      ->check(CLI::ExistingFile);
  cmd->add_option("--press", a->presses, "A press x_mm,y_mm,radius_mm,force_N (repeat for simultaneous presses)");
  cmd->add_option("--script", a->script,
                  "Press script: none (no-contact references), grid, random, two-finger or moving");
  cmd->add_option("--out", job.out_path, "Frames CSV to write")->required();
  cmd->add_option("--truth", job.truth_path, "Presses CSV to write (default: <out>_presses.csv)");
  cmd->add_option("--frames", script.frames, "Frames for the none, random, two-finger and moving scripts")
      ->check(positive_number());
  cmd->add_option("--spacing-mm", script.spacing_mm, "Grid pitch")->check(positive_number());
  cmd->add_option("--jitter-mm", script.jitter_mm, "Grid jitter (uniform, +/-)")->check(non_negative_number());
  cmd->add_option("--radius-mm", script.style.radius_mm, "Indenter radius for scripts")->check(positive_number());
  cmd->add_option("--force-N", a->force_N, "Force, or a range MIN,MAX drawn uniformly")->delimiter(',');
  cmd->add_option("--separation-mm", a->separation_mm, "Two-finger separation range MIN,MAX")->delimiter(',');
  cmd->add_option("--from", a->from_mm, "Moving press start X,Y (mm)")->delimiter(',');
  cmd->add_option("--to", a->to_mm, "Moving press end X,Y (mm)")->delimiter(',');
  cmd->add_option("--margin-mm", a->margin_mm, "Smallest distance from a press centre to the border (default: radius)");
  cmd->add_option("--seed", job.twin.noise_seed, "Seed of the scripts' randomness and of the ADC noise");
  cmd->add_option("--mesh-seed", job.twin.mesh_seed, "Seed of the twin's mesh");
  cmd->add_option("--noise-V", job.noise_V, "Override the ADC noise (standard deviation, V)")
      ->check(non_negative_number());
  cmd->add_flag("--exact", a->exact, "No ADC: exact, noise-free volts");
  cmd->add_option("--sheet-variation", job.twin.sheet_resistance_variation,
                  "Sheet resistance varying linearly along x by +/- this fraction (e.g. 0.2)")
      ->check(CLI::Range(-0.9, 0.9));
  cmd->add_option("--dead-electrode", job.twin.dead_electrode, "Simulate this electrode disconnected")
      ->check(non_negative_integer());
  cmd->add_flag("--table", a->print_table, "Print every frame as an N x N table instead of a summary");
  cmd->add_option("--images", job.images_dir, "Write a PNG of the sheet's potential per frame into this folder");
  cmd->callback([a] { run_simulate(*a); });
}

}  // namespace emit::cli
