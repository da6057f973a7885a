// emit simulate: frames from the digital twin, for given presses or a press script.
#include <cstdio>
#include <filesystem>

#include "commands.hpp"
#include "emit/errors.hpp"
#include "emit/io/frames_csv.hpp"
#include "emit/io/presses_csv.hpp"
#include "emit/mesh/mesh_quality.hpp"
#include "emit/render/field_image.hpp"
#include "emit/twin/press_scripts.hpp"
#include "emit/twin/twin.hpp"

namespace emit::cli {

namespace {

struct SimulateArgs {
  std::string sensor_path, out_path, truth_path, images_dir, script;
  std::vector<std::string> presses;
  int frames = 20;
  double spacing_mm = 10, jitter_mm = 0, radius_mm = 5, margin_mm = -1;
  std::vector<double> force_N{10.0}, separation_mm{12.0, 40.0}, from_mm, to_mm;
  std::uint64_t seed = 1;
  int mesh_seed = 1;
  bool exact = false, print_table = false;
  int dead_electrode = -1;
  double sheet_variation = 0;
  double noise_V = -1;
};

std::vector<double> pair_or_single(const std::vector<double>& values, const char* option) {
  if (values.size() == 1) return {values[0], values[0]};
  if (values.size() == 2) return values;
  throw InvalidInput(std::string(option) + ": give one value or two (a range)");
}

PressSequence presses_of(const Sensor& sensor, const SimulateArgs& a) {
  if (!a.presses.empty() && !a.script.empty()) throw InvalidInput("give --press or --script, not both");
  if (!a.presses.empty()) {
    std::vector<Press> frame;
    for (const auto& text : a.presses) frame.push_back(parse_press(text));
    return {frame};
  }
  if (a.script.empty()) throw InvalidInput("nothing to simulate: give --press x,y,r,F or --script NAME");
  PressStyle style;
  style.radius_mm = a.radius_mm;
  const auto force = pair_or_single(a.force_N, "--force-N");
  style.min_force_N = force[0], style.max_force_N = force[1];
  style.margin_mm = a.margin_mm >= 0 ? a.margin_mm : a.radius_mm;
  style.seed = a.seed;
  if (a.script == "none") return PressSequence(static_cast<std::size_t>(a.frames));  // references
  if (a.script == "grid") return grid_script(sensor, a.spacing_mm, a.jitter_mm, style);
  if (a.script == "random") return random_script(sensor, a.frames, style);
  if (a.script == "two-finger") {
    const auto sep = pair_or_single(a.separation_mm, "--separation-mm");
    return two_finger_script(sensor, a.frames, sep[0], sep[1], style);
  }
  if (a.script == "moving") {
    if (a.from_mm.size() != 2 || a.to_mm.size() != 2) throw InvalidInput("--script moving needs --from X,Y and --to X,Y");
    return moving_script(sensor, a.frames, Vector2(a.from_mm[0], a.from_mm[1]), Vector2(a.to_mm[0], a.to_mm[1]), style);
  }
  throw InvalidInput("--script: unknown script \"" + a.script + "\" (none, grid, random, two-finger, moving)");
}

std::string default_truth_path(const std::string& out_path) {
  std::filesystem::path p(out_path);
  return (p.parent_path() / (p.stem().string() + "_presses.csv")).string();
}

void check_writable_folder(const std::string& path) {
  const auto folder = std::filesystem::path(path).parent_path();
  if (!folder.empty() && !std::filesystem::is_directory(folder))
    throw IoError(path + ": cannot write: folder " + folder.string() + " does not exist");
}

void run_simulate(const SimulateArgs& args) {
  Sensor sensor = sensor_from_option(args.sensor_path);
  if (args.noise_V >= 0) sensor.adc.noise_V = args.noise_V;
  const PressSequence sequence = presses_of(sensor, args);
  for (std::size_t f = 0; f < sequence.size(); ++f)
    for (std::size_t i = 0; i < sequence[f].size(); ++i)
      validate_press(sensor, sequence[f][i], "frame " + std::to_string(f) + ", press " + std::to_string(i));
  const std::string truth_path = args.truth_path.empty() ? default_truth_path(args.out_path) : args.truth_path;
  check_writable_folder(args.out_path);
  check_writable_folder(truth_path);

  std::fprintf(stderr, "meshing the twin of %s ...\n", sensor.name.c_str());
  TwinOptions options;
  options.mesh_seed = args.mesh_seed;
  options.adc = !args.exact;
  options.noise_seed = args.seed;
  options.dead_electrode = args.dead_electrode;
  options.sheet_resistance_variation = args.sheet_variation;
  Twin twin(sensor, options);
  const MeshQuality q = measure_mesh_quality(twin.mesh());
  std::fprintf(stderr, "twin mesh: %lld triangles, %lld nodes, min angle %.1f deg\n",
               static_cast<long long>(q.triangle_count), static_cast<long long>(q.node_count), q.min_angle_deg);

  std::vector<Frame> frames;
  Progress progress("simulating frame", static_cast<int>(sequence.size()));
  for (std::size_t f = 0; f < sequence.size(); ++f) {
    frames.push_back(twin.frame(sequence[f]));
    progress.step(static_cast<int>(f + 1));
  }
  progress.finish();
  write_frames_csv(args.out_path, frames);
  write_presses_csv(truth_path, sequence);
  std::printf("wrote %zu frames of %d electrodes to %s and the presses to %s\n", frames.size(),
              twin.mesh().electrode_count(), args.out_path.c_str(), truth_path.c_str());
  if (args.print_table)
    for (const Frame& frame : frames) print_frame_table(frame);
  else
    print_frames_summary(frames, sequence);

  if (!args.images_dir.empty()) {
    std::filesystem::create_directories(args.images_dir);
    for (std::size_t f = 0; f < sequence.size(); ++f) {
      std::vector<Circle> outlines;
      for (const Press& p : sequence[f]) outlines.push_back({Vector2(p.x_mm, p.y_mm), p.radius_mm});
      FieldImageOptions image;
      image.title = "frame " + std::to_string(f) + ": probing-layer potential, electrode 0 grounded";
      const std::string path = args.images_dir + "/frame_" + std::to_string(f) + ".png";
      write_png(render_field(twin.mesh(), twin.potentials(sequence[f]).col(0), outlines, image), path);
    }
    std::printf("wrote %zu images to %s/\n", sequence.size(), args.images_dir.c_str());
  }
}

}  // namespace

void add_simulate_command(CLI::App& app) {
  auto a = std::make_shared<SimulateArgs>();
  CLI::App* cmd = app.add_subcommand("simulate", "Simulate frames with the digital twin");
  cmd->footer(
      "Examples:\n"
      "  emit simulate --press 30,30,5,10 --out frame.csv\n"
      "  emit simulate --script none --frames 10 --out reference.csv\n"
      "  emit simulate --sensor examples/sensors/square30.json --script grid --spacing-mm 5 --out grid.csv\n"
      "  emit simulate --script two-finger --frames 50 --separation-mm 12,40 --force-N 5,20 --out two.csv\n"
      "  emit simulate --script moving --from 10,10 --to 50,50 --frames 30 --out move.csv");
  cmd->add_option("--sensor", a->sensor_path, "Sensor description (JSON); default: the built-in 60 mm sensor")
      ->check(CLI::ExistingFile);
  cmd->add_option("--press", a->presses, "A press x_mm,y_mm,radius_mm,force_N (repeat for simultaneous presses)");
  cmd->add_option("--script", a->script, "Press script: none (no-contact references), grid, random, two-finger or moving");
  cmd->add_option("--out", a->out_path, "Frames CSV to write")->required();
  cmd->add_option("--truth", a->truth_path, "Presses CSV to write (default: <out>_presses.csv)");
  cmd->add_option("--frames", a->frames, "Frames for the none, random, two-finger and moving scripts")->check(CLI::PositiveNumber);
  cmd->add_option("--spacing-mm", a->spacing_mm, "Grid pitch")->check(CLI::PositiveNumber);
  cmd->add_option("--jitter-mm", a->jitter_mm, "Grid jitter (uniform, +/-)")->check(CLI::NonNegativeNumber);
  cmd->add_option("--radius-mm", a->radius_mm, "Indenter radius for scripts")->check(CLI::PositiveNumber);
  cmd->add_option("--force-N", a->force_N, "Force, or a range MIN,MAX drawn uniformly")->delimiter(',');
  cmd->add_option("--separation-mm", a->separation_mm, "Two-finger separation range MIN,MAX")->delimiter(',');
  cmd->add_option("--from", a->from_mm, "Moving press start X,Y (mm)")->delimiter(',');
  cmd->add_option("--to", a->to_mm, "Moving press end X,Y (mm)")->delimiter(',');
  cmd->add_option("--margin-mm", a->margin_mm, "Smallest distance from a press centre to the border (default: radius)");
  cmd->add_option("--seed", a->seed, "Seed of the scripts' randomness and of the ADC noise");
  cmd->add_option("--mesh-seed", a->mesh_seed, "Seed of the twin's mesh");
  cmd->add_option("--noise-V", a->noise_V, "Override the ADC noise (standard deviation, V)")->check(CLI::NonNegativeNumber);
  cmd->add_flag("--exact", a->exact, "No ADC: exact, noise-free volts");
  cmd->add_option("--sheet-variation", a->sheet_variation,
                  "Sheet resistance varying linearly along x by +/- this fraction (e.g. 0.2)")
      ->check(CLI::Range(-0.9, 0.9));
  cmd->add_option("--dead-electrode", a->dead_electrode, "Simulate this electrode disconnected")
      ->check(CLI::NonNegativeNumber);
  cmd->add_flag("--table", a->print_table, "Print every frame as an N x N table instead of a summary");
  cmd->add_option("--images", a->images_dir, "Write a PNG of the sheet's potential per frame into this folder");
  cmd->callback([a] { run_simulate(*a); });
}

}  // namespace emit::cli
