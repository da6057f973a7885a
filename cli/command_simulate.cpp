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
  std::string profile = "flat";
  CLI::Option* realistic = nullptr;  ///< --realistic [SEED]
  std::string realistic_seed;
  RealisticSheetOptions realistic_options;
  std::vector<double> realistic_drive_V;
  CLI::Option* force = nullptr;  ///< --force-N, given or not (calibration's own range when not)
};

void run_simulate(SimulateArgs a) {
  SimulateJob& job = a.job;
  const PressProfile profile = parse_press_profile(a.profile);
  for (const auto& text : a.presses) {
    job.presses.push_back(parse_press(text));
    job.presses.back().profile = profile;
  }
  if (a.realistic->count() > 0) {
    RealisticSheetOptions& realistic = job.realistic.emplace(a.realistic_options);
    if (!a.realistic_seed.empty()) realistic.seed = parse_seed("--realistic", a.realistic_seed);
    if (!a.realistic_drive_V.empty()) {
      const auto drive = pair_or_single(a.realistic_drive_V, "--realistic-drive-V");
      if (!(drive[0] > 0) || drive[1] < drive[0])
        throw InvalidInput("--realistic-drive-V: give LOW,HIGH volts with 0 < LOW <= HIGH");
      realistic.drive_voltage_low_V = drive[0], realistic.drive_voltage_high_V = drive[1];
    }
  }
  if (!a.script.empty()) {
    PressScript& script = job.script.emplace(a.script_options);
    script.kind = parse_script_kind(a.script);
    const auto force = pair_or_single(a.force_N, "--force-N");
    script.style.min_force_N = force[0], script.style.max_force_N = force[1];
    if (script.kind == PressScript::Kind::calibration) {  // a person calibrating (twin/calibration_person.hpp)
      if (a.force->count() > 0) script.person.min_force_N = force[0], script.person.max_force_N = force[1];
      script.person.radius_mm = script.style.radius_mm;
      script.person.seed = job.twin.noise_seed;
    }
    script.style.margin_mm = a.margin_mm >= 0 ? a.margin_mm : script.style.radius_mm;
    script.style.seed = job.twin.noise_seed;
    script.style.profile = profile;
    const auto separation = pair_or_single(a.separation_mm, "--separation-mm");
    script.min_separation_mm = separation[0], script.max_separation_mm = separation[1];
    if (script.kind == PressScript::Kind::moving) {
      if (a.from_mm.size() != 2 || a.to_mm.size() != 2)
        throw InvalidInput("--script moving needs --from X,Y and --to X,Y");
      script.from_mm = {a.from_mm[0], a.from_mm[1]}, script.to_mm = {a.to_mm[0], a.to_mm[1]};
    }
  }
  job.twin.adc = !a.exact;
  print_simulate_report(job, run_simulate_job(job, stderr_progress()), a.print_table);
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
      "  emit simulate --script moving --from 10,10 --to 50,50 --frames 30 --out move.csv\n"
      "  emit simulate --script three-finger --frames 20 --profile spherical --out three.csv\n"
      "  emit simulate --realistic 7 --script random --frames 30 --out real.csv   (what it drew: real_sheet.json)\n"
      "  emit simulate --realistic --realistic-series-ohm 0 --realistic-blur-mm 2 --press 30,30,5,10 --out f.csv");
  cmd->add_option("--sensor", job.sensor_path, "Sensor description (JSON); default: the built-in 60 mm sensor")
      ->check(CLI::ExistingFile);
  cmd->add_option("--press", a->presses,
                  "A press x_mm,y_mm,radius_mm,force_N, or x_mm,y_mm,z_mm,radius_mm,force_N on a curved sheet; or a "
                  "flat punch's outline on a flat sheet: bar:x,y,length,width,angle_deg,F, ellipse:x,y,a,b,angle_deg,F "
                  "(semi-axes), ring:x,y,inner_r,outer_r,F, polygon:x,y,F,u1,v1,u2,v2,u3,v3[,...] (vertices relative "
                  "to x,y) (repeat for simultaneous presses)");
  cmd->add_option("--script", a->script,
                  "Press script: none (no-contact references), grid, random, two-finger, three-finger, four-finger, "
                  "moving, crossing (two fingers passing each other, their forces crossing) or calibration (a person "
                  "calibrating: 1 s lifted, --presses finger presses covering the sheet, then --weights-N)");
  cmd->add_option("--out", job.out_path, "Frames CSV to write")->required();
  cmd->add_option("--truth", job.truth_path, "Presses CSV to write (default: <out>_presses.csv)");
  cmd->add_option("--frames", script.frames, "Frames for the none, random, two-finger, moving and crossing scripts")
      ->check(positive_integer());
  cmd->add_option("--spacing-mm", script.spacing_mm, "Grid pitch")->check(positive_number());
  cmd->add_option("--jitter-mm", script.jitter_mm, "Grid jitter (uniform, +/-)")->check(non_negative_number());
  cmd->add_option("--radius-mm", script.style.radius_mm, "Indenter radius for scripts")->check(positive_number());
  a->force = cmd->add_option("--force-N", a->force_N, "Force, or a range MIN,MAX drawn uniformly (calibration: 2,39)")
                 ->delimiter(',');
  cmd->add_option("--presses", script.person.presses, "calibration: finger presses (default 60)")
      ->check(non_negative_integer());
  cmd->add_option("--weights-N", script.person.weights_N, "calibration: the known weights put down after (default 2,5)")
      ->delimiter(',')
      ->check(positive_number());
  cmd->add_option("--fps", script.frames_per_s, "calibration: frames per second of the person's time (default 50)")
      ->check(positive_number());
  cmd->add_option("--separation-mm", a->separation_mm,
                  "Two-finger separation range MIN,MAX (crossing: at the closest approach); three- and four-finger: "
                  "MIN, "
                  "the least between any two")
      ->delimiter(',');
  cmd->add_option("--profile", a->profile,
                  "Indenter profile of --press and scripts: flat (uniform) or spherical (Hertz)")
      ->check(CLI::IsMember({"flat", "spherical"}));
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
  RealisticSheetOptions& real = a->realistic_options;
  a->realistic =
      cmd->add_option("--realistic", a->realistic_seed,
                      "A realistic sheet, drawn from SEED (default 1): Rs scaled, a smooth field, electrodes "
                      "shifted, series resistances, the drive voltage, the cover's blur; written to "
                      "<out>_sheet.json")
          ->expected(0, 1);
  const auto realistic_option = [&](const char* name, double& value, const std::string& help,
                                    const CLI::Validator& check) {
    cmd->add_option(name, value, help)->check(check)->needs(a->realistic);
  };
  realistic_option("--realistic-sheet-scale", real.sheet_scale,
                   "Overall sheet resistance off by a factor in [1-S, 1+S] (default 0.3)", fraction_below_one());
  realistic_option("--realistic-field", real.field,
                   "Smooth field's range over the sheet, +/- this fraction (default 0.15)", fraction_below_one());
  realistic_option("--realistic-shift-mm", real.electrode_shift_mm,
                   "Electrodes moved along the border by up to +/- this (default 0.5)", non_negative_number());
  realistic_option("--realistic-series-ohm", real.series_resistance_ohm,
                   "Each electrode's series resistance, uniform in [0, this] (default 300)", non_negative_number());
  realistic_option("--realistic-blur-mm", real.blur_mm, "The cover's Gaussian blur of presses (default 1; 0: none)",
                   non_negative_number());
  cmd->add_option("--realistic-drive-V", a->realistic_drive_V, "Drive voltage range LOW,HIGH (default 3.0,3.3)")
      ->delimiter(',')
      ->needs(a->realistic);
  cmd->add_flag("--table", a->print_table, "Print every frame as an N x N table instead of a summary");
  cmd->add_option("--images", job.images_dir, "Write a PNG of the sheet's potential per frame into this folder");
  cmd->callback([a] { run_simulate(*a); });
}

}  // namespace emit::cli
