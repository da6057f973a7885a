// emit eval: simulate presses with the twin (a finer, different mesh; 12-bit ADC, 1 mV noise),
// reconstruct them, and report positional and pressure errors per method at its best lambda,
// beside the paper's figures.
#include <cctype>
#include <algorithm>
#include <chrono>
#include <optional>
#include <cmath>
#include <cstdio>
#include <numbers>

#include "commands.hpp"
#include "emit/eval/evaluation.hpp"
#include "emit/mesh/generate_mesh.hpp"
#include "emit/reconstruct/jacobian.hpp"
#include "emit/sensor/sensor_json.hpp"
#include <filesystem>

#include "emit/reconstruct/electrode_health.hpp"
#include "emit/fit/fit_model.hpp"
#include "emit/fit/sheet_calibration.hpp"
#include "emit/reconstruct/calibration.hpp"
#include "emit/render/line_plot.hpp"
#include "emit/twin/press_scripts.hpp"
#include "emit/twin/sensor_mismatch.hpp"

namespace emit::cli {

namespace {

struct EvalArgs {
  std::vector<std::string> methods{"paper", "noser", "laplacian", "fit"};
  std::vector<double> lambda2;  // empty: 10^0 … 10^6, eight per decade
  int mesh_seed = 3;
  std::uint64_t seed = 1;
  bool quick = false, sweep = false, mismatches = true;
  std::string plots_dir = "emit-eval";
  std::string sheet;  ///< only the sheets whose name contains this
};

struct EvalCase {
  std::string name;
  Sensor sensor;
  double spacing_mm, jitter_mm, radius_mm;
  const char* paper_position;
  bool pressure_and_two_press;
  int lambdas_per_decade = 8;  ///< of the λ sweep (the 32-electrode sheet's operators cost 10× more)
};

std::vector<EvalCase> eval_cases() {
  const std::string dir = EMIT_EXAMPLES_DIR;
  return {
      {"60 x 60 mm sheet", default_sensor(), 6.0, 2.0, 5.0, "paper: 3.49 +/- 1.56 mm", true},
      {"30 x 30 mm sheet", load_sensor(dir + "/square30.json"), 3.0, 1.0, 2.5, "paper: 1.74 mm", true},
      {"circle, r = 40 mm", load_sensor(dir + "/circle40.json"), 8.0, 2.0, 5.0, "paper: -", false},
      {"120 x 120 mm sheet", load_sensor(dir + "/square120_32.json"), 12.0, 4.0, 5.0, "paper: -", false, 2},
  };
}

/// λ² from 1 to 10⁶.
std::vector<double> default_sweep(int per_decade) {
  std::vector<double> values;
  for (int i = 0; i <= 6 * per_decade; ++i) values.push_back(std::pow(10.0, i / static_cast<double>(per_decade)));
  return values;
}

/// Single presses at random places with pressures uniform in [0.02, 0.5] N/mm² (the paper's range).
PressSequence pressure_presses(const Sensor& sensor, double radius_mm, int frames, std::uint64_t seed) {
  PressStyle style;
  style.radius_mm = radius_mm;
  style.margin_mm = radius_mm + 1;
  style.min_force_N = 0.02 * std::numbers::pi * radius_mm * radius_mm;
  style.max_force_N = 0.5 * std::numbers::pi * radius_mm * radius_mm;
  style.seed = seed;
  return random_script(sensor, frames, style);
}

struct Runs {
  SimulatedRun grid, calibration, test, two_press;
};

Runs simulate_case(const EvalCase& c, const EvalArgs& args) {
  TwinOptions options;
  options.mesh_seed = args.mesh_seed;  // finer than and different from the reconstruction's mesh
  options.noise_seed = args.seed;
  Twin twin(c.sensor, options);
  PressStyle style;
  style.radius_mm = c.radius_mm;
  style.margin_mm = c.radius_mm + 1;
  style.seed = args.seed;
  Runs runs;
  std::fprintf(stderr, "  simulating ...\n");
  runs.grid = simulate_run(twin, grid_script(c.sensor, (args.quick ? 2 : 1) * c.spacing_mm, c.jitter_mm, style));
  if (c.pressure_and_two_press) {
    const int n = args.quick ? 10 : 40;
    runs.calibration = simulate_run(twin, pressure_presses(c.sensor, c.radius_mm, n, args.seed + 100));
    runs.test = simulate_run(twin, pressure_presses(c.sensor, c.radius_mm, n, args.seed + 200));
    PressStyle two = style;
    two.min_force_N = 5 * c.radius_mm * c.radius_mm / 25, two.max_force_N = 20 * c.radius_mm * c.radius_mm / 25;
    const double side = c.sensor.border->size_mm() / std::sqrt(2.0);
    runs.two_press = simulate_run(twin, two_finger_script(c.sensor, n, 0.2 * side, 0.67 * side, two));
  }
  return runs;
}

/// One method's λ sweep, for the plots.
struct SweepCurve {
  std::string method;
  std::vector<double> lambda2, mean_error_mm, residual_norm_V, solution_norm_V;
};

/// \return the best lambda² by the paper's positional error.
double evaluate_method(const EvalCase& c, const Runs& runs, ReconstructionModel& model, const Matrix& J,
                       const std::string& method, const EvalArgs& args, SweepCurve& curve) {
  curve.method = method;
  const std::vector<double> sweep = args.lambda2.empty() ? default_sweep(c.lambdas_per_decade) : args.lambda2;
  model.options = method_options(method);
  const OperatorFamily family(J, model.mesh, model.options.prior, model.options.noser_exponent);
  LocalisationResult best;
  double best_lambda2 = 0;
  for (double lambda2 : sweep) {
    model.options.lambda2 = lambda2;
    model.op = family.compact_operator_for(lambda2, model.options.rank_cutoff);
    Reconstructor reconstructor(model, PressureCalibration::uncalibrated(c.sensor));
    const LocalisationResult r = localisation_errors(reconstructor, runs.grid, 0.5);
    const LCurvePoint l = l_curve_point(J, model.op, model.measurements, runs.grid);
    curve.lambda2.push_back(lambda2);
    curve.mean_error_mm.push_back(r.image_centroid.mean);
    curve.residual_norm_V.push_back(l.residual_norm_V);
    curve.solution_norm_V.push_back(l.solution_norm_V);
    if (args.sweep)
      std::printf("    %-10s lambda2 %9.3g: %6.2f +/- %5.2f mm (contact: %6.2f mm)\n", method.c_str(), lambda2,
                  r.image_centroid.mean, r.image_centroid.std, r.strongest_contact.mean);
    if (best_lambda2 == 0 || r.image_centroid.mean < best.image_centroid.mean) best = r, best_lambda2 = lambda2;
  }
  const ErrorStats& e = best.image_centroid;
  std::printf("  %-10s %9.3g  %5.2f +/- %4.2f  %6.2f %6.2f  %6.2f  ", method.c_str(), best_lambda2, e.mean, e.std,
              e.median, e.p95, best.strongest_contact.mean);
  if (c.pressure_and_two_press) {
    model.options.lambda2 = best_lambda2;
    model.op = family.compact_operator_for(best_lambda2, model.options.rank_cutoff);
    Reconstructor reconstructor(model, PressureCalibration::uncalibrated(c.sensor));
    const PressureResult p = pressure_errors(reconstructor, runs.calibration, runs.test, 0.5);
    const TwoPressResult two = two_press_rates(reconstructor, runs.two_press, 0.4 * c.radius_mm * 4);
    std::printf("%7.4f (%4.1f %%)  %5.0f %%  %5.0f %%", p.error_N_per_mm2.mean, 100 * p.error_N_per_mm2.mean / 0.5,
                100 * two.two_contacts, 100 * two.both_matched);
  }
  std::printf("\n");
  return best_lambda2;
}

/// Fitted contacts' pressure after `emit calibrate --method fit` on the calibration run: the
/// mean |error| on the test run.
double fit_pressure_error(Reconstructor& reconstructor, const EvalCase& c, const Runs& runs) {
  const auto pressures = [](const SimulatedRun& run) {
    std::vector<double> out;
    for (const auto& presses : run.presses) out.push_back(presses.at(0).pressure_N_per_mm2());
    return out;
  };
  reconstructor.set_reference(runs.calibration.reference);
  const ContactLaw law =
      calibrate_fitted_contact_law(reconstructor, runs.calibration.frames, pressures(runs.calibration), c.sensor.contact).law;
  reconstructor.set_reference(runs.test.reference);
  const std::vector<double> truth = pressures(runs.test);
  std::vector<double> errors;
  for (std::size_t f = 0; f < runs.test.frames.size(); ++f) {
    reconstructor.process(runs.test.frames[f]);
    const FitResult& fit = *reconstructor.fit_result();
    if (fit.contacts.empty()) continue;
    errors.push_back(std::abs(law.pressure_N_per_mm2(fit.contacts[0].disc.conductance_S_per_mm2) - truth[f]));
  }
  return summarize_errors(errors, 0).mean;
}

/// Model-based contact fitting, seeded by the paper method's image.
void evaluate_fit(const EvalCase& c, const Runs& runs, ReconstructionModel model, const Matrix& J) {
  model.options = method_options("paper");
  model.op = build_compact_operator(J, model.mesh, model.options);
  const FitModel fit_model = build_fit_model(c.sensor);
  ContactFitter fitter(c.sensor, fit_model.mesh, fit_model.green, model.measurements);
  Reconstructor reconstructor(model, PressureCalibration::uncalibrated(c.sensor));
  reconstructor.use_fitter(&fitter);
  const auto start = std::chrono::steady_clock::now();
  const LocalisationResult r = localisation_errors(reconstructor, runs.grid, 0.5);
  const double ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count() /
                    static_cast<double>(runs.grid.frames.size());
  const ErrorStats& e = r.strongest_contact;
  std::printf("  %-10s %9s  %5.2f +/- %4.2f  %6.2f %6.2f  %6.2f  ", "fit", "-", e.mean, e.std, e.median, e.p95, e.mean);
  if (c.pressure_and_two_press) {
    const double p = fit_pressure_error(reconstructor, c, runs);
    const TwoPressResult two = two_press_rates(reconstructor, runs.two_press, 2.0);
    std::printf("%7.4f (%4.1f %%)  %5.0f %%  %5.0f %%", p, 100 * p / 0.5, 100 * two.two_contacts, 100 * two.both_matched);
  }
  std::printf("  (%.0f ms a frame, %d mesh nodes; 2 match: within 2 mm)\n", ms, static_cast<int>(fit_model.mesh.node_count()));
}

/// The twin departs from the description; the reconstruction keeps the nominal one (and leaves
/// out electrodes it finds dead, as `emit reconstruct` does).
void evaluate_mismatches(const EvalCase& c, const std::string& method, double lambda2, const EvalArgs& args,
                         const FitModel* fit_model) {
  std::printf("  mismatches (twin differs, reconstruction nominal; %s at lambda2 = %.3g):\n", method.c_str(), lambda2);
  TwinOptions base;
  base.mesh_seed = args.mesh_seed;
  base.noise_seed = args.seed;
  OperatorOptions options = method_options(method);
  options.lambda2 = lambda2;
  PressStyle style;
  style.radius_mm = c.radius_mm;
  style.margin_mm = c.radius_mm + 1;
  style.seed = args.seed;
  const PressSequence grid = grid_script(c.sensor, (args.quick ? 2 : 1) * c.spacing_mm, c.jitter_mm, style);
  for (const Mismatch& m : standard_mismatches(c.sensor, base, args.seed)) {
    Twin twin(m.twin_sensor, m.twin_options);
    const SimulatedRun run = simulate_run(twin, grid);
    std::vector<int> dead;
    for (const DeadElectrode& d : find_dead_electrodes(run.frames, c.sensor.adc)) dead.push_back(d.electrode);
    const ReconstructionModel model = build_reconstruction_model(c.sensor, options, "", dead);
    Reconstructor reconstructor(model, PressureCalibration::uncalibrated(c.sensor));
    const ErrorStats e = localisation_errors(reconstructor, run, 0.5).image_centroid;
    std::printf("    %-46s %5.2f +/- %4.2f mm (median %.2f, p95 %.2f)", m.name.c_str(), e.mean, e.std, e.median, e.p95);
    std::printf("%s\n", dead.empty() ? "" : ", dead electrode found and left out");
    if (fit_model) {
      ContactFitter fitter(c.sensor, fit_model->mesh, fit_model->green, model.measurements);
      reconstructor.use_fitter(&fitter);
      const ErrorStats f = localisation_errors(reconstructor, run, 0.5).strongest_contact;
      const SimulatedRun calibration = simulate_run(twin, pressure_presses(c.sensor, c.radius_mm, args.quick ? 10 : 40, args.seed + 100));
      const SheetCorrection correction =
          calibrate_sheet(c.sensor, fit_model->mesh, model.measurements, calibration.frames, calibration.reference, calibration.presses)
              .correction;
      const DenseGreenFunction green = fit_green_function(fit_model->mesh, c.sensor, &correction);
      ContactFitter corrected(c.sensor, fit_model->mesh, green, model.measurements);
      reconstructor.use_fitter(&corrected);
      const ErrorStats s = localisation_errors(reconstructor, run, 0.5).strongest_contact;
      const auto [low, high] = correction.factor_range(fit_model->mesh);
      std::printf("    %46s fit: %5.2f +/- %4.2f mm (p95 %.2f); sheet self-calibrated (x%.2f..%.2f): %5.2f +/- %4.2f mm (p95 %.2f)\n",
                  "", f.mean, f.std, f.p95, low, high, s.mean, s.std, s.p95);
    }
  }
}

std::string file_stem(const std::string& name) {
  std::string stem;
  for (char ch : name)
    if (std::isalnum(static_cast<unsigned char>(ch))) stem += static_cast<char>(std::tolower(static_cast<unsigned char>(ch)));
    else if (!stem.empty() && stem.back() != '_') stem += '_';
  while (!stem.empty() && stem.back() == '_') stem.pop_back();
  return stem;
}

/// Error versus λ², and the L-curve (image norm versus misfit, λ² labelled every decade).
void write_plots(const EvalCase& c, const std::vector<SweepCurve>& curves, const std::string& dir) {
  std::vector<PlotSeries> errors, l_curves;
  for (std::size_t i = 0; i < curves.size(); ++i) {
    const SweepCurve& s = curves[i];
    if (s.lambda2.empty()) continue;  // a method without λ (fit)
    errors.push_back({s.method, s.lambda2, s.mean_error_mm, series_colour(static_cast<int>(i)), true, {}});
    PlotSeries l{s.method, s.residual_norm_V, s.solution_norm_V, series_colour(static_cast<int>(i)), true, {}};
    for (double lambda2 : s.lambda2) {
      const double decade = std::log10(lambda2);
      char label[24] = "";
      if (std::abs(decade - std::round(decade)) < 1e-9 && static_cast<long>(std::round(decade)) % 2 == 0)
        std::snprintf(label, sizeof label, "1e%ld", static_cast<long>(std::round(decade)));
      l.point_labels.push_back(label);
    }
    l_curves.push_back(l);
  }
  if (errors.empty()) return;  // no method with a λ (fit alone): nothing to plot
  std::filesystem::create_directories(dir);
  const std::string stem = dir + "/" + file_stem(c.name);
  PlotOptions options;
  options.title = c.name + ": positional error versus λ²";
  options.x_label = "λ²";
  options.y_label = "mean error (mm)";
  options.log_x = true;
  write_png(render_line_plot(errors, options), stem + "_error_vs_lambda.png");
  options.title = c.name + ": L-curve (labels: λ²)";
  options.x_label = "misfit |J·δφ - δV| (V)";
  options.y_label = "image norm |δφ| (V)";
  options.log_x = options.log_y = true;
  write_png(render_line_plot(l_curves, options), stem + "_l_curve.png");
  std::printf("  plots: %s_error_vs_lambda.png, %s_l_curve.png\n", stem.c_str(), stem.c_str());
}

void run_eval(const EvalArgs& args) {
  std::printf("emit eval: twin on a finer mesh (seed %d), 12-bit ADC, 1 mV noise; %s grid of single presses\n",
              args.mesh_seed, args.quick ? "a coarse" : "a jittered");
  std::printf("position: the paper's estimate (centroid of the image above 50 %% of its max); also the strongest\n"
              "contact's centroid. pressure: after calibration on separate presses, |error| vs 0.5 N/mm2 full scale.\n");
  for (const EvalCase& c : eval_cases()) {
    if (c.name.find(args.sheet) == std::string::npos) continue;
    std::printf("\n%s, %d electrodes (%s; pressure paper: 0.0457 N/mm2)\n", c.name.c_str(), c.sensor.electrode_count(),
                c.paper_position);
    const Runs runs = simulate_case(c, args);
    ReconstructionModel model;
    model.mesh = generate_mesh(c.sensor, reconstruction_mesh_options(c.sensor));
    model.measurements = make_measurement_set(model.mesh.electrode_count());
    const Matrix J = compute_jacobian(model.mesh, model.measurements);
    std::printf("  %zu single presses (r = %.1f mm), reconstruction mesh %lld triangles\n", runs.grid.presses.size(),
                c.radius_mm, static_cast<long long>(model.mesh.triangle_count()));
    std::printf("  %-10s %9s  %13s  %6s %6s  %6s  %16s  %6s  %6s\n", "method", "lambda2", "mean +/- std", "median",
                "p95", "contact", "pressure N/mm2", "2 found", "2 match");
    double paper_lambda2 = 0;
    std::vector<SweepCurve> curves(args.methods.size());
    for (std::size_t i = 0; i < args.methods.size(); ++i) {
      if (args.methods[i] == "fit") {
        evaluate_fit(c, runs, model, J);
        continue;
      }
      const double best = evaluate_method(c, runs, model, J, args.methods[i], args, curves[i]);
      if (args.methods[i] == "paper") paper_lambda2 = best;
    }
    if (!args.plots_dir.empty()) write_plots(c, curves, args.plots_dir);
    if (c.pressure_and_two_press && paper_lambda2 > 0 && args.mismatches) {
      const bool with_fit = std::find(args.methods.begin(), args.methods.end(), "fit") != args.methods.end();
      const std::optional<FitModel> fit_model = with_fit ? std::optional<FitModel>(build_fit_model(c.sensor)) : std::nullopt;
      evaluate_mismatches(c, "paper", paper_lambda2, args, fit_model ? &*fit_model : nullptr);
    }
  }
}

}  // namespace

void add_eval_command(CLI::App& app) {
  auto a = std::make_shared<EvalArgs>();
  CLI::App* cmd = app.add_subcommand("eval", "Measure reconstruction accuracy on the digital twin");
  cmd->add_option("--methods", a->methods, "Methods to evaluate")->delimiter(',')->capture_default_str();
  cmd->add_option("--lambda2", a->lambda2, "lambda^2 values to sweep (default: 1 to 1e6, 8 per decade)")->delimiter(',');
  cmd->add_option("--mesh-seed", a->mesh_seed, "Seed of the twin's mesh")->capture_default_str();
  cmd->add_option("--seed", a->seed, "Seed of the presses and of the ADC noise")->capture_default_str();
  cmd->add_flag("--sweep", a->sweep, "Print every lambda of the sweep");
  cmd->add_option("--sheet", a->sheet, "Only the sheets whose name contains this (60, 30, circle, 120)");
  cmd->add_flag("--quick", a->quick, "Fewer presses (a smoke test)");
  cmd->add_flag("!--no-mismatches", a->mismatches, "Skip the sensor-mismatch runs");
  cmd->add_option("--plots", a->plots_dir, "Folder for the error-versus-lambda and L-curve plots (\"\": none)")
      ->capture_default_str();
  cmd->callback([a] { run_eval(*a); });
}

}  // namespace emit::cli
