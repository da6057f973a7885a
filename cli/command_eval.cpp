// emit eval: simulate presses with the twin (a finer, different mesh; 12-bit ADC, 1 mV noise),
// reconstruct them, and report positional and pressure errors per method at its best lambda,
// beside the paper's figures (eval/sheet_evaluation.hpp); with --realistic, the round a user
// runs with a real sheet, on a realistic one, beside issue 14's targets
// (eval/realistic_evaluation.hpp).
#include <cstdio>
#include <sstream>
#include <string>

#include "commands.hpp"
#include "emit/core/errors.hpp"
#include "emit/core/quote_input.hpp"
#include "emit/eval/realistic_evaluation.hpp"
#include "emit/eval/sheet_evaluation.hpp"
#include "emit/jobs/real_eval_job.hpp"
#include "emit/pipeline/pipeline.hpp"

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
  RealEvalJob real;  ///< --real DIR: a real skin's presses
  long long test_from = -1;
  std::vector<std::string> curve;  ///< --curve: numbers, or "none"
};

/// `--realistic`'s SEED: a whole number 0 or larger (not CLI11's unsigned parse, which takes -1).
std::uint64_t parse_seed(const std::string& text) {
  std::size_t used = 0;
  std::uint64_t seed = 0;
  try {
    seed = std::stoull(text, &used);
  } catch (const std::exception&) {
    used = 0;
  }
  if (used == 0 || used != text.size() || text[0] == '-')
    throw InvalidInput("--realistic: the seed must be a whole number 0 or larger, got " + quote_input(text));
  return seed;
}

/// The standard sheets whose name begins with `sheet` (all for ""): "60" is the 60 mm sheet, not
/// the sleeve 60 mm long. \throw InvalidInput if none.
std::vector<EvalCase> matching_cases(const std::string& sheet) {
  std::vector<EvalCase> cases = standard_eval_cases(examples_dir());
  std::erase_if(cases, [&](const EvalCase& c) { return c.name.rfind(sheet, 0) != 0; });
  if (cases.empty())
    throw InvalidInput("--sheet " + quote_input(sheet) +
                       ": no sheet's name begins with it (60, 30, circle, 120, dome, sleeve, fingertip)");
  return cases;
}

/// `emit eval --realistic`: the realistic round on each chosen sheet (the 60 mm one by default).
void run_realistic(EvalArgs& args) {
  RealisticEvalOptions& o = args.realistic_options;
  if (!args.realistic_seed.empty()) o.sheet.seed = parse_seed(args.realistic_seed);
  o.mesh_seed = args.options.mesh_seed;
  if (args.seed->count() > 0) o.seed = args.options.seed;
  if (args.options.quick) o.counts = quick_realistic_counts();
  o.validate();
  const std::vector<EvalCase> cases = matching_cases(args.sheet.empty() ? "60" : args.sheet);
  std::printf(
      "emit eval --realistic %llu: the round of README \"A realistic sheet\" on the twin (mesh seed %d; noise "
      "and presses from seed %llu), beside issue 14's targets%s\n",
      static_cast<unsigned long long>(o.sheet.seed), o.mesh_seed, static_cast<unsigned long long>(o.seed),
      args.options.quick ? " (--quick: a smoke test, too few presses to judge by)" : "");
  for (const EvalCase& c : cases) {
    std::printf("\n%s, %d electrodes, realistic sheet %llu\n", c.name.c_str(), electrode_count_of(c.sensor),
                static_cast<unsigned long long>(o.sheet.seed));
    std::fflush(stdout);
    const RealisticEvaluation e = evaluate_realistic_sheet(c, o, stderr_progress());
    std::istringstream description(e.sheet_description);
    for (std::string line; std::getline(description, line);) std::printf("  | %s\n", line.c_str());
    print_realistic_evaluation(e);
  }
}

/// The automatic λ² (no --lambda2) beside the sweep's best, and what the significance test and
/// the reference's averaging do.
void print_automatic(const MethodEvaluation& m) {
  const double best_relative = m.spectrum_scale > 0 ? m.lambda2 / m.spectrum_scale : 0;
  const double relative = m.spectrum_scale > 0 ? m.auto_lambda2 / m.spectrum_scale : 0;
  std::printf("    auto lambda2 %9.3g (%.3g x spectrum scale; best %.3g): %5.2f mm, %+.0f %% of the best\n",
              m.auto_lambda2, relative, best_relative, m.auto_position.mean,
              m.position.mean > 0 ? 100 * (m.auto_position.mean / m.position.mean - 1) : 0.0);
  std::printf(
      "      false contacts: %4.1f %% of single presses (every region: %4.1f %%), "
      "%4.1f %% of no-press frames (%4.1f %%)\n",
      100 * m.false_contacts, 100 * m.false_contacts_untested, 100 * m.noise_contacts, 100 * m.noise_contacts_untested);
  std::printf("      reference: one frame alone %.2f .. %.2f mm; ten with one very noisy %.2f mm",
              m.single_reference_low_mm, m.single_reference_high_mm, m.noisy_reference_mm);
  if (m.auto_two_press)
    std::printf("; two presses %3.0f %% found, %3.0f %% matched", 100 * m.auto_two_press->two_contacts,
                100 * m.auto_two_press->both_matched);
  std::printf("\n");
}

void print_method(const EvalCase& c, const MethodEvaluation& m, bool sweep) {
  if (sweep)
    for (const SweepPoint& p : m.sweep)
      std::printf("    %-10s lambda2 %9.3g: %6.2f +/- %5.2f mm (contact: %6.2f mm)\n", method_name(m.method), p.lambda2,
                  p.image_centroid.mean, p.image_centroid.std, p.strongest_contact.mean);
  char lambda[16] = "-";
  if (is_linear(m.method)) std::snprintf(lambda, sizeof lambda, "%9.3g", m.lambda2);
  const ErrorStats& e = m.position;
  std::printf("  %-10s %9s  %5.2f +/- %4.2f  %6.2f %6.2f  %6.2f  ", method_name(m.method), lambda, e.mean, e.std,
              e.median, e.p95, m.strongest_contact.mean);
  if (c.pressure_and_two_press && m.pressure_error_N_per_mm2 && m.two_press)
    std::printf("%7.4f (%4.1f %%)  %5.0f %%  %5.0f %%", *m.pressure_error_N_per_mm2,
                100 * *m.pressure_error_N_per_mm2 / 0.5, 100 * m.two_press->two_contacts,
                100 * m.two_press->both_matched);
  if (!is_linear(m.method))
    std::printf("  (%.0f ms a frame, %ld mesh nodes; 2 match: within 2 mm)", m.ms_per_frame, m.fit_mesh_nodes);
  std::printf("\n");
  if (is_linear(m.method)) print_automatic(m);
}

void print_mismatches(const SheetEvaluation& e) {
  std::printf("  mismatches (twin differs, reconstruction nominal; paper at lambda2 = %.3g):\n", e.mismatch_lambda2);
  for (const MismatchEvaluation& m : e.mismatches) {
    std::printf("    %-46s %5.2f +/- %4.2f mm (median %.2f, p95 %.2f)%s\n", m.name.c_str(), m.paper.mean, m.paper.std,
                m.paper.median, m.paper.p95, m.dead_electrode_found ? ", dead electrode found and left out" : "");
    if (m.fit && m.fit_self_calibrated)
      std::printf(
          "    %46s fit: %5.2f +/- %4.2f mm (p95 %.2f); sheet self-calibrated (x%.2f..%.2f): %5.2f +/- %4.2f mm "
          "(p95 %.2f)\n",
          "", m.fit->mean, m.fit->std, m.fit->p95, m.sheet_factor_low, m.sheet_factor_high, m.fit_self_calibrated->mean,
          m.fit_self_calibrated->std, m.fit_self_calibrated->p95);
  }
}

void print_stats(const char* what, const ErrorStats& e) {
  std::printf("  %-44s %6.2f +/- %5.2f mm (median %.2f, p95 %.2f; %d presses%s)\n", what, e.mean, e.std, e.median,
              e.p95, e.count, e.missed > 0 ? (", " + std::to_string(e.missed) + " not found").c_str() : "");
}

/// `emit eval --real DIR --sensor S`: a real skin's presses, calibrated on the first N.
void run_real(EvalArgs& args) {
  RealEvalJob& job = args.real;
  if (job.sensor_path.empty()) throw InvalidInput("--real: give the skin's description with --sensor FILE");
  job.options.test_from = static_cast<Index>(args.test_from);
  if (!args.curve.empty()) {
    job.options.curve.clear();
    if (args.curve != std::vector<std::string>{"none"})
      for (std::string n : args.curve) {
        if (const std::string error = positive_integer()(n); !error.empty())
          throw InvalidInput("--curve: " + error + " (or none)");
        job.options.curve.push_back(std::stol(n));
      }
  }
  job.plots_dir = args.plots_dir;
  const RealEvalReport report = run_real_eval_job(job, stderr_progress(20));
  const RealEvaluation& e = report.evaluation;
  std::printf("emit eval --real %s: %s, %ld presses of %ld readings; calibrated on presses 0-%ld, held out %ld-%ld\n",
              job.folder.c_str(), report.sensor_name.c_str(), static_cast<long>(e.presses),
              static_cast<long>(e.readings), static_cast<long>(e.calibration_presses - 1),
              static_cast<long>(e.test_from), static_cast<long>(e.presses - 1));
  std::printf("  press response: degree %d, shrinkage %.1f (chosen by %d-fold cross-validation: %.2f mm)\n",
              e.fit.kept.degree, e.fit.kept.shrinkage, job.options.fit.folds, e.fit.kept.cross_validated_mm);
  print_stats("held-out presses, position error", e.held_out);
  print_stats("always answering the presses' centre", e.held_out_centre);
  if (e.held_out_image) {
    const std::string what = "physics alone (NOSER image, " + std::to_string(e.image_triangles) + " triangles)";
    print_stats(what.c_str(), *e.held_out_image);
  }
  std::printf("  %.2f ms a frame\n", e.ms_per_frame);
  std::printf("  against calibration presses (held-out mean; cross-validated; degree):\n");
  for (const RealCurvePoint& p : e.curve)
    std::printf("    %4ld presses: %6.2f mm   %6.2f mm   %d\n", static_cast<long>(p.calibration_presses),
                p.held_out.mean, p.kept.cross_validated_mm, p.kept.degree);
  if (!job.contacts_path.empty())
    std::printf("  contacts: %s (presses %ld on)\n", job.contacts_path.c_str(),
                static_cast<long>(e.calibration_presses));
  if (!report.plot_path.empty()) std::printf("  plot: %s\n", report.plot_path.c_str());
}

void run_eval(EvalArgs args) {
  if (!args.real.folder.empty()) return run_real(args);
  if (args.realistic->count() > 0) return run_realistic(args);
  args.options.methods.clear();
  for (const std::string& name : args.methods) args.options.methods.push_back(parse_method(name));
  const std::vector<EvalCase> cases = matching_cases(args.sheet);
  std::printf("emit eval: twin on a finer mesh (seed %d), 12-bit ADC, 1 mV noise; %s grid of single presses\n",
              args.options.mesh_seed, args.options.quick ? "a coarse" : "a jittered");
  std::printf(
      "position: the paper's estimate (centroid of the image above 50 %% of its max); also the strongest\n"
      "contact's centroid. pressure: after calibration on separate presses, |error| vs 0.5 N/mm2 full scale.\n");
  for (const EvalCase& c : cases) {
    std::printf("\n%s, %d electrodes (%s; pressure paper: 0.0457 N/mm2)\n", c.name.c_str(),
                electrode_count_of(c.sensor), c.paper_position.c_str());
    std::fflush(stdout);
    const SheetEvaluation e = evaluate_sheet(c, args.options, stderr_progress());
    std::printf("  %zu single presses (r = %.1f mm), reconstruction mesh %ld triangles\n", e.grid_presses, c.radius_mm,
                e.triangles);
    std::printf("  %-10s %9s  %13s  %6s %6s  %6s  %16s  %6s  %6s\n", "method", "lambda2", "mean +/- std", "median",
                "p95", "contact", "pressure N/mm2", "2 found", "2 match");
    for (const MethodEvaluation& m : e.methods) print_method(c, m, args.sweep);
    if (!args.plots_dir.empty())
      if (const auto plots = write_sweep_plots(c, e, args.plots_dir); !plots.empty())
        std::printf("  plots: %s, %s\n", plots[0].c_str(), plots[1].c_str());
    if (!e.mismatches.empty()) print_mismatches(e);
  }
}

}  // namespace

void add_eval_command(CLI::App& app) {
  auto a = std::make_shared<EvalArgs>();
  EvalOptions& o = a->options;
  CLI::App* cmd = app.add_subcommand("eval", "Measure reconstruction accuracy on the digital twin");
  cmd->add_option("--methods", a->methods, "Methods to evaluate")
      ->delimiter(',')
      ->check(CLI::IsMember(method_names()))
      ->capture_default_str();
  cmd->add_option("--lambda2", o.lambda2, "lambda^2 values to sweep (default: 1 to 1e6, 8 per decade)")->delimiter(',');
  cmd->add_option("--mesh-seed", o.mesh_seed, "Seed of the twin's mesh")->capture_default_str();
  a->seed =
      cmd->add_option("--seed", o.seed, "Seed of the presses and of the ADC noise (default 1; with --realistic, 11)");
  cmd->add_flag("--sweep", a->sweep, "Print every lambda of the sweep");
  cmd->add_option("--sheet", a->sheet,
                  "Only the sheets whose name begins with this (60, 30, circle, 120, dome, sleeve, fingertip)");
  cmd->add_flag("--quick", o.quick, "Fewer presses (a smoke test)");
  a->realistic = cmd->add_option("--realistic", a->realistic_seed,
                                 "The round a user runs with a real sheet, on a realistic sheet drawn from SEED "
                                 "(default 3): calibrate, reconstruct, score against issue 14's targets; only the "
                                 "60 mm sheet unless --sheet says; --methods, --lambda2 and the sweep do not apply")
                     ->expected(0, 1)
                     ->type_name("[SEED]");
  CLI::Option* real =
      cmd->add_option("--real", a->real.folder,
                      "A real skin's presses: a folder of frames.csv, references_per_frame.csv (or reference.csv) and "
                      "truth.csv (README \"Current-injection skins on real data\"); calibrate on the first presses, "
                      "locate the rest")
          ->type_name("DIR");
  cmd->add_option("--sensor", a->real.sensor_path, "With --real: the skin's description, with its \"excitation\"")
      ->type_name("FILE")
      ->needs(real);
  cmd->add_option("--calibration-presses", a->real.options.calibration_presses,
                  "With --real: calibrate on this many first presses")
      ->check(positive_integer())
      ->capture_default_str()
      ->needs(real);
  cmd->add_option("--test-from", a->test_from, "With --real: the held-out presses begin here (default: the last fifth)")
      ->check(positive_integer())
      ->needs(real);
  cmd->add_option("--curve", a->curve,
                  "With --real: the numbers of calibration presses to measure the error against, or none "
                  "(default 20,30,50,75,100,150,200,300,440; those past the held-out presses are skipped)")
      ->delimiter(',')
      ->needs(real);
  cmd->add_option("--contacts", a->real.contacts_path,
                  "With --real: write the located presses as JSON Lines (\"frame\": the row of frames.csv)")
      ->type_name("FILE")
      ->needs(real);
  cmd->add_flag("!--no-mismatches", o.mismatches, "Skip the sensor-mismatch runs");
  cmd->add_option("--plots", a->plots_dir, "Folder for the error-versus-lambda and L-curve plots (\"\": none)")
      ->capture_default_str();
  cmd->callback([a] { run_eval(*a); });
}

}  // namespace emit::cli
