// emit eval: simulate presses with the twin (finer, different mesh; 12-bit ADC, 1 mV noise),
// reconstruct them, and report positional errors per method and lambda beside the paper's.
#include <cmath>
#include <cstdio>

#include "commands.hpp"
#include "emit/eval/error_stats.hpp"
#include "emit/mesh/generate_mesh.hpp"
#include "emit/reconstruct/jacobian.hpp"
#include "emit/reconstruct/reconstructor.hpp"
#include "emit/sensor/sensor_json.hpp"
#include "emit/twin/press_scripts.hpp"
#include "emit/twin/twin.hpp"

namespace emit::cli {

namespace {

struct EvalArgs {
  std::vector<std::string> methods{"paper", "noser", "laplacian"};
  std::vector<double> lambda2{1e-4, 1e-3, 1e-2, 1e-1, 1, 10, 100, 1000};
  int mesh_seed = 3;
  std::uint64_t seed = 1;
  bool quick = false;
};

struct EvalCase {
  std::string name;
  Sensor sensor;
  double spacing_mm, jitter_mm, radius_mm, margin_mm;
  std::string paper_figure;
};

std::vector<EvalCase> cases(const std::string& examples) {
  return {
      {"60 mm sheet", default_sensor(), 6.0, 2.0, 5.0, 6.0, "3.49 +/- 1.56 mm (paper, hardware)"},
      {"30 mm sheet", load_sensor(examples + "/square30.json"), 3.0, 1.0, 2.5, 3.0, "1.74 mm (paper, 30 mm area)"},
  };
}

struct SimulatedRun {
  PressSequence presses;
  std::vector<Frame> frames;
  Frame reference;
};

SimulatedRun simulate(const EvalCase& c, const EvalArgs& args) {
  PressStyle style;
  style.radius_mm = c.radius_mm;
  style.margin_mm = c.margin_mm;
  style.seed = args.seed;
  SimulatedRun run;
  run.presses = grid_script(c.sensor, args.quick ? 2 * c.spacing_mm : c.spacing_mm, c.jitter_mm, style);
  TwinOptions options;
  options.mesh_seed = args.mesh_seed;  // the twin's mesh: finer than and different from the reconstruction's
  options.noise_seed = args.seed;
  Twin twin(c.sensor, options);
  std::vector<Frame> references;
  for (int i = 0; i < 10; ++i) references.push_back(twin.frame({}));
  run.reference = average_frames(references);
  Progress progress("  simulating", static_cast<int>(run.presses.size()));
  for (std::size_t f = 0; f < run.presses.size(); ++f) {
    run.frames.push_back(twin.frame(run.presses[f]));
    progress.step(static_cast<int>(f + 1));
  }
  progress.finish();
  return run;
}

ErrorStats localise(const ReconstructionModel& model, const SimulatedRun& run, const Sensor& sensor) {
  Reconstructor reconstructor(model, PressureCalibration::uncalibrated(sensor));
  reconstructor.set_reference(run.reference);
  std::vector<double> errors;
  int missed = 0;
  for (std::size_t f = 0; f < run.frames.size(); ++f) {
    const double e = single_press_error_mm(reconstructor.process(run.frames[f]), run.presses[f][0]);
    if (e < 0) ++missed;
    else errors.push_back(e);
  }
  return summarize_errors(errors, missed);
}

void run_eval(const EvalArgs& args) {
  std::printf("emit eval: twin mesh seed %d, %s, ADC 12 bit with 1 mV noise; errors in mm over a jittered grid\n",
              args.mesh_seed, args.quick ? "quick grid" : "full grid");
  for (const EvalCase& c : cases(std::string(EMIT_EXAMPLES_DIR))) {
    std::printf("\n%s (%d electrodes)\n", c.name.c_str(), c.sensor.electrode_count());
    const SimulatedRun run = simulate(c, args);
    ReconstructionModel model;
    model.mesh = generate_mesh(c.sensor, reconstruction_mesh_options(c.sensor));
    model.measurements = make_measurement_set(model.mesh.electrode_count());
    const Matrix J = compute_jacobian(model.mesh, model.measurements);
    std::printf("  %zu presses; reconstruction mesh %lld triangles\n", run.presses.size(),
                static_cast<long long>(model.mesh.triangle_count()));
    std::printf("  %-10s %10s %8s %8s %8s %8s %7s\n", "method", "lambda2", "mean", "std", "median", "p95", "missed");
    for (const std::string& method : args.methods) {
      ErrorStats best;
      double best_lambda2 = 0;
      for (double lambda2 : args.lambda2) {
        model.options = method_options(method);
        model.options.lambda2 = lambda2;
        model.op = build_reconstruction_operator(J, model.mesh, model.options);
        const ErrorStats s = localise(model, run, c.sensor);
        std::printf("  %-10s %10.3g %8.2f %8.2f %8.2f %8.2f %7d\n", method.c_str(), lambda2, s.mean, s.std, s.median,
                    s.p95, s.missed);
        if (best_lambda2 == 0 || s.mean < best.mean) best = s, best_lambda2 = lambda2;
      }
      std::printf("  %-10s best at lambda2 = %g: %.2f +/- %.2f mm (median %.2f, p95 %.2f); %s\n", method.c_str(),
                  best_lambda2, best.mean, best.std, best.median, best.p95, c.paper_figure.c_str());
    }
  }
}

}  // namespace

void add_eval_command(CLI::App& app) {
  auto a = std::make_shared<EvalArgs>();
  CLI::App* cmd = app.add_subcommand("eval", "Measure reconstruction accuracy on the digital twin");
  cmd->add_option("--methods", a->methods, "Methods to evaluate")->delimiter(',')->capture_default_str();
  cmd->add_option("--lambda2", a->lambda2, "lambda^2 values to sweep")->delimiter(',');
  cmd->add_option("--mesh-seed", a->mesh_seed, "Seed of the twin's mesh")->capture_default_str();
  cmd->add_option("--seed", a->seed, "Seed of the press jitter and the ADC noise")->capture_default_str();
  cmd->add_flag("--quick", a->quick, "A coarser grid (for smoke tests)");
  cmd->callback([a] { run_eval(*a); });
}

}  // namespace emit::cli
