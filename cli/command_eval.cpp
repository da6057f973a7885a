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
  std::vector<EvalCase> cases = standard_eval_cases(EMIT_EXAMPLES_DIR);
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

void run_eval(EvalArgs args) {
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
  cmd->add_flag("!--no-mismatches", o.mismatches, "Skip the sensor-mismatch runs");
  cmd->add_option("--plots", a->plots_dir, "Folder for the error-versus-lambda and L-curve plots (\"\": none)")
      ->capture_default_str();
  cmd->callback([a] { run_eval(*a); });
}

}  // namespace emit::cli
