// emit eval: accuracy per method on the twin beside the paper's figures; --realistic, a user's
// round on a realistic sheet beside its targets; --outlines, pressed regions of many outlines per
// method; --tracking, touches over time (ids through crossings, the filter's jitter and lag);
// --real, a real skin's presses (jobs/eval_job.hpp, jobs/real_eval_job.hpp; their tables:
// eval_tables.cpp, realistic_eval_table.cpp, outline_eval_table.cpp).
#include <cstdio>
#include <cstdlib>
#include <sstream>
#include <string>
#include <utility>

#include "commands.hpp"
#include "emit/calibrate/sensor_calibration.hpp"
#include "emit/core/errors.hpp"
#include "emit/jobs/eval_job.hpp"
#include "emit/jobs/real_eval_job.hpp"
#include "eval_merit.hpp"

namespace emit::cli {

namespace {

struct EvalArgs {
  EvalOptions options;
  std::vector<std::string> methods{"paper", "noser", "laplacian", "fit"};
  bool sweep = false;
  std::string plots_dir = "emit-eval";
  std::string sheet;                 ///< only the sheets whose name begins with this
  CLI::Option* realistic = nullptr;  ///< --realistic [SEED]
  CLI::Option* seed = nullptr;       ///< --seed, given or not
  std::string realistic_seed;
  RealisticEvalOptions realistic_options;
  RealEvalJob real;                   ///< --real DIR: a real skin's presses
  bool outlines = false;              ///< --outlines
  bool indenters = false;             ///< --indenters
  bool tracking = false;              ///< --tracking
  int crossings = 0;                  ///< --crossings (0: the evaluation's own)
  std::vector<double> separation_mm;  ///< --separation-mm MIN,MAX
  TrackerOptions tracker;             ///< --track-gate-mm, --track-coast-frames
  long long test_from = -1;
  int calibration_presses = 0;     ///< --calibration-presses (0: the evaluation's own)
  std::vector<std::string> curve;  ///< --curve: numbers, or "none"
  MeritEvalArgs merit;             ///< --figures-of-merit, --resolvability
};

/// `emit eval --realistic`: the realistic round on each chosen sheet (the 60 mm one by default).
void run_realistic(EvalArgs& args) {
  RealisticEvalOptions& o = args.realistic_options;
  if (!args.realistic_seed.empty()) o.sheet.seed = parse_seed("--realistic", args.realistic_seed);
  o.mesh_seed = args.options.mesh_seed;
  if (args.seed->count() > 0) o.seed = args.options.seed;
  if (args.options.quick) o.counts = quick_realistic_counts();
  if (args.calibration_presses > 0) {
    if (args.calibration_presses < least_calibration_presses)
      throw InvalidInput("--calibration-presses: a sheet's calibration takes " +
                         std::to_string(least_calibration_presses) + " presses or more, got " +
                         std::to_string(args.calibration_presses));
    o.counts.calibration_presses = args.calibration_presses;
  }
  o.validate();
  const std::vector<EvalSheet> sheets = eval_sheets(examples_dir(), args.sheet.empty() ? "60" : args.sheet);
  std::printf(
      "emit eval --realistic %llu: the round of README \"A realistic sheet\" on the twin (mesh seed %d; noise "
      "and presses from seed %llu), beside its targets%s\n",
      static_cast<unsigned long long>(o.sheet.seed), o.mesh_seed, static_cast<unsigned long long>(o.seed),
      args.options.quick ? " (--quick: a smoke test, too few presses to judge by)" : "");
  for (const auto& [c, electrodes] : sheets) {
    std::printf("\n%s, %d electrodes, realistic sheet %llu\n", c.name.c_str(), electrodes,
                static_cast<unsigned long long>(o.sheet.seed));
    std::fflush(stdout);
    const RealisticEvaluation e = run_realistic_eval_job(c, o, stderr_progress());
    std::istringstream description(e.sheet_description);
    for (std::string line; std::getline(description, line);) std::printf("  | %s\n", line.c_str());
    print_realistic_evaluation(e);
  }
}

/// `emit eval --outlines`: pressed outlines per method on each chosen sheet (the 60 mm one by default).
void run_outlines(EvalArgs& args) {
  OutlineEvalOptions o = args.options.quick ? quick_outline_options() : OutlineEvalOptions{};
  o.methods.clear();
  for (const std::string& name : args.methods) o.methods.push_back(parse_method(name));
  o.mesh_seed = args.options.mesh_seed;
  if (args.seed->count() > 0) o.seed = args.options.seed;
  o.indenters = args.indenters;
  o.validate();
  const std::vector<EvalSheet> sheets = eval_sheets(examples_dir(), args.sheet.empty() ? "60" : args.sheet);
  std::printf("emit eval %s on the twin (mesh seed %d; noise and presses from seed %llu), %d of each, 4-16 N%s\n",
              o.indenters ? "--indenters: flat discs of radius 2, 3, 5, 7 and 10 mm"
                          : "--outlines: flat punches of eight outlines",
              o.mesh_seed, static_cast<unsigned long long>(o.seed), o.presses_per_family,
              args.options.quick ? " (--quick: a smoke test, too few presses to judge by)" : "");
  for (const auto& [c, electrodes] : sheets) {
    std::printf("\n%s, %d electrodes\n", c.name.c_str(), electrodes);
    std::fflush(stdout);
    print_outline_evaluation(run_outline_eval_job(c, o, stderr_progress()));
  }
}

/// `emit eval --tracking`: touches over time on each chosen sheet (the 60 mm one by default).
void run_tracking(EvalArgs& args) {
  TrackingEvalOptions o = args.options.quick ? quick_tracking_options() : TrackingEvalOptions{};
  o.mesh_seed = args.options.mesh_seed;
  if (args.seed->count() > 0) o.seed = args.options.seed;
  if (args.crossings > 0) o.crossings = args.crossings;
  o.tracker = args.tracker;
  if (!args.separation_mm.empty()) {
    const auto separation = pair_or_single(args.separation_mm, "--separation-mm");
    o.min_separation_mm = separation[0], o.max_separation_mm = separation[1];
  }
  o.validate();
  const std::vector<EvalSheet> sheets = eval_sheets(examples_dir(), args.sheet.empty() ? "60" : args.sheet);
  std::printf(
      "emit eval --tracking on the twin (mesh seed %d; noise and presses from seed %llu), contact fitting as emit "
      "live runs it, %g frames/s: %d crossings of two fingers (%d-%d frames, %g-%g mm apart, forces %g-%g N "
      "crossing), a %g N press held still for %d frames, steps%s\n",
      o.mesh_seed, static_cast<unsigned long long>(o.seed), o.frames_per_s, o.crossings, o.min_frames, o.max_frames,
      o.min_separation_mm, o.max_separation_mm, o.min_force_N, o.max_force_N, o.still_force_N, o.still_frames,
      args.options.quick ? " (--quick: a smoke test, too few crossings to judge by)" : "");
  for (const auto& [c, electrodes] : sheets) {
    std::printf("\n%s, %d electrodes\n", c.name.c_str(), electrodes);
    std::fflush(stdout);
    const TrackingEvaluation e = run_tracking_eval_job(c, o, stderr_progress());
    for (const auto& [name, score] : {std::pair{"unfiltered", e.unfiltered}, std::pair{"filtered", e.filtered}})
      std::printf(
          "  crossings, %-10s: ids kept (no swap) in %d of %d = %.1f %% (target >= 99 %%); a finger's id changed "
          "otherwise in %d; one down and one up per finger in %d\n",
          name, score.trials - score.swapped, score.trials, 100 * score.swap_free(), score.broken, score.right_events);
    std::printf("  frames where a finger had no contact within 5 mm: %d of %d\n", e.frames_missing_a_finger,
                e.crossing_frames);
    std::printf("  still %g N press: jitter %.4f mm rms unfiltered, %.4f mm filtered (target <= 0.05 mm)\n",
                o.still_force_N, e.jitter_mm, e.filtered_jitter_mm);
    for (const StepLag& s : e.steps)
      std::printf("  step of %g mm: within 10 %% of it after %d frames filtered, %d unfiltered (target <= 1)\n",
                  s.step_mm, s.lag_frames, s.raw_lag_frames);
    std::printf("  reconstruction %.1f ms a frame; tracking %.2f us a frame\n", e.reconstruct_ms_per_frame,
                e.track_us_per_frame);
  }
}

/// `emit eval --real DIR --sensor S`: a real skin's presses, calibrated on the first N.
void run_real(EvalArgs& args) {
  RealEvalJob& job = args.real;
  if (job.sensor_path.empty()) throw InvalidInput("--real: give the skin's description with --sensor FILE");
  job.options.test_from = static_cast<Index>(args.test_from);
  if (args.calibration_presses > 0) job.options.calibration_presses = args.calibration_presses;
  if (!args.curve.empty()) job.options.curve.clear();
  if (args.curve != std::vector<std::string>{"none"})
    for (std::string n : args.curve) {
      if (const std::string error = press_count()(n); !error.empty())
        throw InvalidInput("--curve: give numbers or none; each " + error);
      job.options.curve.push_back(static_cast<Index>(std::strtod(n.c_str(), nullptr)));
    }
  job.plots_dir = args.plots_dir;
  print_real_evaluation(job, run_real_eval_job(job, stderr_progress(20)));
}

void run_eval(EvalArgs args) {
  if (args.calibration_presses > 0 && args.real.folder.empty() && args.realistic->count() == 0)
    throw InvalidInput("--calibration-presses: give it with --real or --realistic");
  if (!args.real.folder.empty()) return run_real(args);
  if (args.realistic->count() > 0) return run_realistic(args);
  if (args.outlines || args.indenters) return run_outlines(args);
  if (args.tracking) return run_tracking(args);
  args.options.methods.clear();
  for (const std::string& name : args.methods) args.options.methods.push_back(parse_method(name));
  if (run_merit_eval(args.merit, args.sheet, args.options.methods, args.options.mesh_seed, args.options.seed,
                     args.options.quick))
    return;
  const std::vector<EvalSheet> sheets = eval_sheets(examples_dir(), args.sheet);
  std::printf("emit eval: twin on a finer mesh (seed %d), 12-bit ADC, 1 mV noise; %s grid of single presses\n",
              args.options.mesh_seed, args.options.quick ? "a coarse" : "a jittered");
  std::printf(
      "position: the paper's estimate (centroid of the image above 50 %% of its max); also the strongest\n"
      "contact's centroid. pressure: after calibration on separate presses, |error| vs 0.5 N/mm2 full scale.\n");
  for (const auto& [c, electrodes] : sheets) {
    std::printf("\n%s, %d electrodes (%s; pressure paper: 0.0457 N/mm2)\n", c.name.c_str(), electrodes,
                c.paper_position.c_str());
    std::fflush(stdout);
    print_sheet_evaluation(c, run_sheet_eval_job(c, args.options, args.plots_dir, stderr_progress()), args.sweep);
  }
}

}  // namespace

void add_eval_command(CLI::App& app) {
  auto a = std::make_shared<EvalArgs>();
  EvalOptions& o = a->options;
  CLI::App* cmd = app.add_subcommand(
      "eval", "Measure how well emit images presses: on the digital twin, its realistic sheets, or a real skin's data");
  cmd->footer(
      "Examples:\n  emit eval --quick                  every method on every sheet, a few presses each\n"
      "  emit eval --realistic 3            calibrate and image a realistic sheet, beside the targets\n"
      "  emit eval --real DIR --sensor SKIN.json   a real skin's presses (README, \"Your own board\")");
  cmd->add_option("--methods", a->methods, "Methods to evaluate")
      ->delimiter(',')
      ->check(CLI::IsMember(method_names()))
      ->capture_default_str();
  cmd->add_option("--lambda2", o.lambda2, "lambda^2 values to sweep (default: 1 to 1e6, 8 per decade)")->delimiter(',');
  cmd->add_option("--mesh-seed", o.mesh_seed, "Seed of the twin's mesh")->capture_default_str();
  a->seed = cmd->add_option("--seed", o.seed,
                            "Seed of the presses and of the ADC noise (default 1; with --realistic, 11; with "
                            "--outlines and --indenters, 21; with --tracking, 31)");
  cmd->add_flag("--sweep", a->sweep, "Print every lambda of the sweep");
  cmd->add_option("--sheet", a->sheet,
                  "Only the sheets whose name begins with this (60, 30, circle, 120, dome, sleeve, fingertip)");
  cmd->add_flag("--quick", o.quick, "Fewer presses (a smoke test)");
  a->realistic = cmd->add_option("--realistic", a->realistic_seed,
                                 "The round a user runs with a real sheet, on a realistic sheet drawn from SEED "
                                 "(default 3): calibrate, reconstruct, score against the round's targets; only the "
                                 "60 mm sheet unless --sheet says; --methods, --lambda2 and the sweep do not apply")
                     ->expected(0, 1)
                     ->type_name("[SEED]");
  cmd->add_option("--unplaced", a->realistic_options.unplaced_known_forces,
                  "With --realistic: calibrate as in the field, every calibration press's place unknown and only "
                  "the first K of known force (the targets are then 0.5 mm mean, 1.0 mm p95, 0.02 N/mm2)")
      ->type_name("K")
      ->needs(a->realistic);
  cmd->add_flag("--outlines", a->outlines,
                "Pressed regions of flat punches of eight outlines (bars, an ellipse, a ring, a palm, an L, two "
                "bars, a stylus) per method, each calibrated on 40 disc presses: Dice, force, centroid, "
                "orientation and regions per outline (the 60 mm sheet unless --sheet says; --lambda2 does not apply)")
      ->excludes(a->realistic);
  cmd->add_flag("--indenters", a->indenters,
                "As --outlines, with flat discs of radius 2, 3, 5, 7 and 10 mm for outlines after the same calibration "
                "with 5 mm discs: area, force and whether they lie within their reported 1 and 2 sigma; fit and shapes "
                "also with each radius declared (--contact-radius-mm)")
      ->excludes(a->realistic)
      ->excludes("--outlines");
  CLI::Option* tracking =
      cmd->add_flag("--tracking", a->tracking,
                    "Touches over time with contact fitting (the 60 mm sheet unless --sheet says): two fingers "
                    "crossing, their forces crossing (ids kept, downs and ups), a 5 N press held still (jitter, "
                    "unfiltered and filtered) and steps (lag)")
          ->excludes(a->realistic)
          ->excludes("--outlines")
          ->excludes("--indenters");
  cmd->add_option("--crossings", a->crossings, "With --tracking: this many crossings (default 200; --quick: 4)")
      ->check(positive_integer())
      ->needs(tracking);
  cmd->add_option("--track-gate-mm", a->tracker.gate_mm, "With --tracking: the tracker's gate")
      ->check(checked_by(&TrackerOptions::gate_mm))
      ->needs(tracking);
  cmd->add_option("--track-coast-frames", a->tracker.coast_frames,
                  "With --tracking: frames a touch may go unseen before it ends")
      ->check(non_negative_integer())
      ->needs(tracking);
  cmd->add_option("--separation-mm", a->separation_mm,
                  "With --tracking: the fingers' distance at the closest approach, MIN,MAX (default 12,20)")
      ->delimiter(',')
      ->needs(tracking);
  CLI::Option* real =
      cmd->add_option("--real", a->real.folder,
                      "A real skin's presses: a folder of frames.csv, references_per_frame.csv (or reference.csv) and "
                      "truth.csv (README \"Current-injection skins on real data\"); calibrate on the first presses, "
                      "locate the rest")
          ->type_name("DIR");
  cmd->add_option("--sensor", a->real.sensor_path, "With --real: the skin's description, with its \"excitation\"")
      ->type_name("FILE")
      ->needs(real);
  cmd->add_option("--calibration-presses", a->calibration_presses,
                  "With --real: calibrate on this many first presses (default 100); with --realistic: this many "
                  "presses calibrate the sheet (default 40, at least 8)")
      ->check(press_count());
  cmd->add_option("--test-from", a->test_from, "With --real: the held-out presses begin here (default: the last fifth)")
      ->check(press_count())
      ->needs(real);
  cmd->add_option("--curve", a->curve,
                  "With --real: the numbers of calibration presses to measure the error against, or none "
                  "(default 20,30,50,75,100,150,200,300,440; those past the held-out presses are skipped)")
      ->delimiter(',')
      ->needs(real);
  cmd->add_option("--rail", a->real.options.readings.rail,
                  "With --real: the board's largest reading (its ADC's rail); a reading at or above it is clipped and "
                  "left out (default: found from the data, the largest value when it recurs in 1 % of the frames)")
      ->type_name("VALUE")
      ->check(CLI::PositiveNumber)
      ->needs(real);
  cmd->add_option("--contacts", a->real.contacts_path,
                  "With --real: write the located presses as JSON Lines (\"frame\": the row of frames.csv)")
      ->type_name("FILE")
      ->needs(real);
  add_merit_eval_options(cmd, a->merit);
  cmd->add_flag("!--no-mismatches", o.mismatches, "Skip the sensor-mismatch runs");
  cmd->add_option("--plots", a->plots_dir, "Folder for the error-versus-lambda and L-curve plots (\"\": none)")
      ->capture_default_str();
  cmd->callback([a] { run_eval(*a); });
}

}  // namespace emit::cli
