// emit calibrate: fit eq. 8's a1, a2, a3 from presses of known force (and eq. 2's alpha, gamma
// from resistance-pressure pairs).
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <optional>
#include <fstream>
#include <functional>
#include <sstream>

#include "commands.hpp"
#include "emit/errors.hpp"
#include "emit/fit/fit_model.hpp"
#include "emit/fit/sheet_calibration.hpp"
#include "emit/io/calibration_json.hpp"
#include "emit/io/frames_csv.hpp"
#include "emit/io/presses_csv.hpp"
#include "emit/reconstruct/calibration.hpp"
#include "emit/reconstruct/operator_cache.hpp"

namespace emit::cli {

namespace {

struct CalibrateArgs {
  std::string sensor_path, reference_path, frames_path, truth_path, out_path, contact_law_path, method = "fit", cache_dir;
  double lambda2 = 0, threshold = 0.5;
  bool sheet = true;  ///< with --method fit: also fit the sheet's resistance
};

/// Contact fitting's calibration: the sheet's resistance (unless --no-sheet) from where the
/// presses were, then the contact law as the fit sees it, on the corrected sheet.
void calibrate_fitting(const CalibrateArgs& args, const Sensor& sensor, const ReconstructionModel& model,
                       Reconstructor& reconstructor, const Frame& reference, const std::vector<Frame>& frames,
                       const PressSequence& truth, const std::function<void(const std::string&)>& say) {
  std::vector<Frame> single;
  std::vector<double> pressures;
  PressureCalibration calibration;
  calibration.calibrated = true;
  for (std::size_t f = 0; f < frames.size(); ++f) {
    if (truth[f].size() != 1) continue;  // calibrate on single presses only
    calibration.indenter_radius_mm += truth[f][0].radius_mm;
    single.push_back(frames[f]);
    pressures.push_back(truth[f][0].pressure_N_per_mm2());
  }
  if (single.empty()) throw InvalidInput(args.truth_path + ": no single presses to calibrate on");
  calibration.indenter_radius_mm /= static_cast<double>(single.size());
  say("meshing the sheet for contact fitting");
  FitModel fit_model{fit_mesh(sensor), {}};
  if (args.sheet) {
    const SheetCalibration sheet = calibrate_sheet(sensor, fit_model.mesh, model.measurements, frames, reference, truth, say);
    calibration.sheet_correction = sheet.correction;
    const auto [low, high] = sheet.correction.factor_range(fit_model.mesh);
    std::printf("fitted the sheet's resistance on %d presses: its conductance is %.3f to %.3f times the nominal; "
                "misfit %.3f mV -> %.3f mV rms\n",
                sheet.presses, low, high, 1e3 * sheet.rms_misfit_nominal_V, 1e3 * sheet.rms_misfit_corrected_V);
  }
  say("Green's function (" + std::to_string(fit_model.mesh.node_count()) + " nodes)");
  fit_model.green =
      fit_green_function(fit_model.mesh, sensor, calibration.sheet_correction ? &*calibration.sheet_correction : nullptr);
  ContactFitter fitter(sensor, fit_model.mesh, fit_model.green, model.measurements);
  reconstructor.use_fitter(&fitter);
  const FittedLawCalibration fitted = calibrate_fitted_contact_law(reconstructor, single, pressures, sensor.contact);
  calibration.fitted_contact_law = fitted.law;
  write_calibration(args.out_path, calibration);
  std::printf("fitted the contact law R = alpha P^gamma as the fit sees it, on %zu presses: alpha = %.6g, gamma = %.6g; "
              "contacts will be reported with the presses' mean indenter radius, %.2f mm\n",
              fitted.presses, fitted.law.alpha_ohm_mm2, fitted.law.gamma, calibration.indenter_radius_mm);
  std::printf("residuals: rms %.4f N/mm2, largest %.4f N/mm2 (%.1f %% of a 0.5 N/mm2 full scale); wrote %s\n",
              fitted.rms_N_per_mm2, fitted.max_abs_N_per_mm2, 100 * fitted.max_abs_N_per_mm2 / 0.5, args.out_path.c_str());
}

void fit_pressure(const CalibrateArgs& args) {
  const Sensor sensor = sensor_from_option(args.sensor_path);
  const bool fit = args.method == "fit";  // fitting is seeded by the paper method's image
  OperatorOptions options = method_options(fit ? "paper" : args.method);
  if (args.lambda2 > 0) options.lambda2 = args.lambda2;
  const auto say = [](const std::string& stage) { std::fprintf(stderr, "%s ...\n", stage.c_str()); };
  const ReconstructionModel model =
      build_reconstruction_model(sensor, options, args.cache_dir.empty() ? default_cache_dir() : args.cache_dir, {}, say);
  const int N = model.mesh.electrode_count();
  const Frame reference = average_frames(read_frames_csv(args.reference_path, N));
  const std::vector<Frame> frames = read_frames_csv(args.frames_path, N);
  const PressSequence truth = read_presses_csv(args.truth_path);
  if (truth.size() != frames.size())
    throw InvalidInput(args.truth_path + ": " + std::to_string(truth.size()) + " frames of presses for " +
                       std::to_string(frames.size()) + " frames in " + args.frames_path);
  FrameOptions frame_options;
  frame_options.threshold_fraction = args.threshold;
  Reconstructor reconstructor(model, PressureCalibration::uncalibrated(sensor), frame_options);
  reconstructor.set_reference(reference);
  if (fit) return calibrate_fitting(args, sensor, model, reconstructor, reference, frames, truth, say);
  std::vector<PressureSample> samples;
  for (std::size_t f = 0; f < frames.size(); ++f) {
    if (truth[f].size() != 1) continue;  // calibrate on single presses only
    reconstructor.process(frames[f]);
    samples.push_back(pressure_sample(reconstructor, args.threshold, truth[f][0].pressure_N_per_mm2()));
  }
  const PressureFit result = fit_pressure_calibration(samples);
  write_calibration(args.out_path, result.calibration);
  std::printf("fitted P = (a1/dphi + a2)^a3 on %zu presses (%s, lambda2 = %g): a1 = %.6g, a2 = %.6g, a3 = %.6g\n",
              samples.size(), args.method.c_str(), options.lambda2, result.calibration.a1, result.calibration.a2,
              result.calibration.a3);
  std::printf("residuals: rms %.4f N/mm2, largest %.4f N/mm2 (%.1f %% of a 0.5 N/mm2 full scale); wrote %s\n",
              result.rms_N_per_mm2, result.max_abs_N_per_mm2, 100 * result.max_abs_N_per_mm2 / 0.5, args.out_path.c_str());
}

void fit_law(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw IoError(path + ": cannot open resistance-pressure pairs");
  std::vector<double> pressure, resistance;
  std::string line;
  for (int number = 1; std::getline(in, line); ++number) {
    if (number == 1 && line.find_first_of("0123456789") != 0) continue;  // a header
    double p = 0, r = 0;
    if (std::sscanf(line.c_str(), "%lf,%lf", &p, &r) != 2)
      throw InvalidInput(path + ":" + std::to_string(number) + ": expected pressure_N_per_mm2,resistance_ohm");
    pressure.push_back(p), resistance.push_back(r);
  }
  const ContactLawFit fit = fit_contact_law(pressure, resistance);
  std::printf("fitted R = alpha P^gamma on %zu pairs: alpha = %.6g, gamma = %.6g (rms relative residual %.3g)\n",
              pressure.size(), fit.alpha, fit.gamma, fit.rms_relative);
}

void run_calibrate(const CalibrateArgs& args) {
  const bool pressure = !args.frames_path.empty();
  if (pressure && (args.reference_path.empty() || args.truth_path.empty() || args.out_path.empty()))
    throw InvalidInput("pressure calibration needs --reference, --frames, --truth and --out");
  if (!pressure && args.contact_law_path.empty())
    throw InvalidInput("nothing to calibrate: give --frames (with --reference, --truth, --out) or --contact-law");
  if (!args.contact_law_path.empty()) fit_law(args.contact_law_path);
  if (pressure) fit_pressure(args);
}

}  // namespace

void add_calibrate_command(CLI::App& app) {
  auto a = std::make_shared<CalibrateArgs>();
  CLI::App* cmd = app.add_subcommand("calibrate", "Fit the pressure calibration (paper eq. 8) from known presses");
  cmd->footer("Example:\n  emit calibrate --reference ref.csv --frames presses.csv --truth presses_presses.csv --out calib.json");
  cmd->add_option("--sensor", a->sensor_path, "Sensor description (JSON); default: the built-in 60 mm sensor")
      ->check(CLI::ExistingFile);
  cmd->add_option("--reference", a->reference_path, "No-contact frames (CSV)")->check(CLI::ExistingFile);
  cmd->add_option("--frames", a->frames_path, "Frames of single presses of known force (CSV)")->check(CLI::ExistingFile);
  cmd->add_option("--truth", a->truth_path, "The presses (CSV: frame,x_mm,y_mm,radius_mm,force_N,...)")
      ->check(CLI::ExistingFile);
  cmd->add_option("--out", a->out_path, "Calibration to write (JSON)");
  cmd->add_option("--contact-law", a->contact_law_path, "Also fit eq. 2 from pairs (CSV: pressure_N_per_mm2,resistance_ohm)")
      ->check(CLI::ExistingFile);
  cmd->add_option("--method", a->method, "Reconstruction method the calibration is for")
      ->check(CLI::IsMember({"fit", "paper", "noser", "laplacian"}))
      ->capture_default_str();
  cmd->add_option("--lambda2", a->lambda2, "lambda^2 (default: the method's)")->check(CLI::PositiveNumber);
  cmd->add_option("--threshold", a->threshold, "Threshold fraction")->capture_default_str();
  cmd->add_flag("!--no-sheet", a->sheet,
                "With --method fit: keep the nominal sheet resistance instead of fitting its variation from the presses");
  cmd->add_option("--cache", a->cache_dir, "Operator cache folder (default: $EMIT_CACHE_DIR or ~/.cache/emit)");
  cmd->callback([a] { run_calibrate(*a); });
}

}  // namespace emit::cli
