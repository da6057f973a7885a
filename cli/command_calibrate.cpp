// emit calibrate: a method's calibration from presses of known place and force (eq. 8's a1, a2,
// a3 for the linear methods; the sheet and the contact law as contact fitting sees them), and
// eq. 2's alpha, gamma from resistance-pressure pairs.
#include <unistd.h>
#include <cstdio>
#include <optional>

#include "commands.hpp"
#include "emit/core/errors.hpp"
#include "emit/jobs/calibrate_job.hpp"
#include "emit/jobs/capture_job.hpp"
#include "stop_on_signals.hpp"

namespace emit::cli {

namespace {

struct CalibrateArgs {
  CalibrateJob job;
  std::string method = "fit";
  CaptureJob capture;  ///< with --capture
};

/// The sensor's self-calibration: each parameter with its 1σ, which the presses determine and
/// which they leave to the prior, the goodness of fit, and any doubt.
void print_sensor_fit(const SensorCalibration& s, double factor_low, double factor_high) {
  std::printf(
      "fitted the sensor on %d presses: misfit %.3f mV -> %.3f mV rms (chi2 per reading %.2f; 1 is the noise)\n"
      "  sheet conductance %.3f to %.3f times the nominal; drive %.4f V\n",
      s.presses, 1e3 * s.rms_misfit_nominal_V, 1e3 * s.rms_misfit_corrected_V, s.chi2_per_reading, factor_low,
      factor_high, s.drive_voltage_V);
  std::printf("  %-40s %12s %12s %12s  %s\n", "parameter", "value", "1 sigma", "prior sigma", "determined");
  for (const CalibratedParameter& p : s.parameters)
    std::printf("  %-40s %12.5g %12.3g %12.3g  %s\n", p.name.c_str(), p.value, p.std, p.prior_std,
                p.determined ? "yes" : "no: the prior holds it");
  std::size_t placed = 0;
  for (std::size_t i = 0; i < s.centres_mm.size(); ++i) {
    if (!s.place_fitted[i]) continue;
    if (placed++ == 0) std::printf("  places fitted to the presses of unknown place (chart mm; also in the report):\n");
    std::printf("    press %zu at (%.2f, %.2f)\n", i, s.centres_mm[i].x(), s.centres_mm[i].y());
  }
  std::printf(
      "  not determined by presses: the sheet's overall resistance (only series resistance x sheet conductance is "
      "seen), a contact's radial spread (indenter profile, cover blur); the contact law absorbs both\n");
  for (const std::string& w : s.warnings) std::fprintf(stderr, "emit: warning: calibration: %s\n", w.c_str());
}

void print_presses(const CalibrateJob& job, const PressCalibrationResult& r) {
  if (const auto* fit = std::get_if<FitCalibration>(&r.calibration)) {
    if (r.sheet) print_sensor_fit(*r.sheet, r.sheet_factor_low, r.sheet_factor_high);
    std::printf(
        "fitted the contact law R = alpha P^gamma as the fit sees it, on %zu presses: alpha = %.6g, gamma = %.6g; "
        "contacts will be reported with the presses' mean indenter radius, %.2f mm\n",
        r.presses, fit->contact_law.alpha_ohm_mm2, fit->contact_law.gamma, fit->indenter_radius_mm);
  } else {
    const auto& linear = std::get<LinearCalibration>(r.calibration);
    std::printf("fitted P = (a1/dphi + a2)^a3 on %zu presses (%s, lambda2 = %g): a1 = %.6g, a2 = %.6g, a3 = %.6g\n",
                r.presses, method_name(job.options.method), r.lambda2, linear.a1, linear.a2, linear.a3);
    if (const std::optional<ImageForceLaw>& f = linear.force_law)
      std::printf(
          "fitted the force F = (b1/I + b2)^b3 on the image's integral I over %zu presses: b1 = %.6g V mm2, b2 = "
          "%.6g, b3 = %.6g; mean |force error| %.1f %% (rms log %.3f); contacts will be reported with the presses' "
          "mean indenter radius, %.2f mm\n",
          r.force_presses, f->b1_V_mm2, f->b2, f->b3, 100 * r.force_error, f->log_std, f->indenter_radius_mm);
  }
  std::printf("residuals: rms %.4f N/mm2, largest %.4f N/mm2 (%.1f %% of a 0.5 N/mm2 full scale); wrote %s\n",
              r.rms_N_per_mm2, r.max_abs_N_per_mm2, 100 * r.max_abs_N_per_mm2 / 0.5, job.out_path.c_str());
}

/// --capture: the person is told each step on stderr, the status on one line rewritten in place on a
/// terminal; Ctrl-C keeps what was captured (exit 130), a source that ends early is an error (exit 1).
void run_capture(CalibrateArgs& args) {
  if (!args.job.reference_path.empty() || !args.job.frames_path.empty() || !args.job.truth_path.empty())
    throw InvalidInput(
        "--capture records the reference, frames and presses itself: give none of --reference, "
        "--frames, --truth");
  CaptureJob& capture = args.capture;
  capture.calibrate = args.job;
  const bool terminal = isatty(fileno(stderr)) != 0;
  bool status_shown = false;
  CaptureSay say;
  say.line = [&](const std::string& text) {
    std::fprintf(stderr, "%s%s\n", status_shown ? "\r\033[K" : "", text.c_str());
    status_shown = false;
  };
  say.status = [&](const std::string& text) {
    if (!terminal) return;  // a log gets the lines alone
    std::fprintf(stderr, "\r\033[K%s", text.c_str());
    std::fflush(stderr);
    status_shown = true;
  };
  const StopOnSignals signals;
  const CaptureReport report = run_capture_job(capture, StopOnSignals::flag(), say, stderr_progress());
  if (report.stopped) throw ExitCode{130};
  if (!report.ended.empty()) throw IoError("--capture " + capture.source_spec + ": " + report.ended);
  if (report.calibration && report.calibration->presses) print_presses(args.job, *report.calibration->presses);
}

void run_calibrate(CalibrateArgs args) {
  CalibrateJob& job = args.job;
  job.options.method = parse_method(args.method);
  job.options.cache_dir = cache_dir_option(job.options.cache_dir, false);
  if (!args.capture.source_spec.empty()) return run_capture(args);
  const CalibrateReport report = run_calibrate_job(job, stderr_progress());
  if (report.contact_law)
    std::printf("fitted R = alpha P^gamma on %zu pairs: alpha = %.6g, gamma = %.6g (rms relative residual %.3g)\n",
                report.pairs, report.contact_law->alpha, report.contact_law->gamma, report.contact_law->rms_relative);
  if (report.presses) print_presses(job, *report.presses);
}

}  // namespace

void add_calibrate_command(CLI::App& app) {
  auto a = std::make_shared<CalibrateArgs>();
  CalibrateJob& job = a->job;
  CLI::App* cmd =
      app.add_subcommand("calibrate",
                         "Calibrate a sensor from presses: fit its sheet, electrodes and contact law (or, for the "
                         "paper's "
                         "linear methods, their pressure scale), from presses of known place and force or guided live "
                         "(--capture)");
  cmd->footer(
      "Example:\n  emit calibrate --reference ref.csv --frames presses.csv --truth presses_presses.csv --out "
      "calib.json");
  cmd->add_option("--sensor", job.sensor_path, "Sensor description (JSON); default: the built-in 60 mm sensor")
      ->check(CLI::ExistingFile);
  cmd->add_option("--reference", job.reference_path, "No-contact frames (CSV)")->check(CLI::ExistingFile);
  cmd->add_option("--frames", job.frames_path, "Frames of single presses of known force (CSV)")
      ->check(CLI::ExistingFile);
  cmd->add_option("--truth", job.truth_path, "The presses (CSV: frame,x_mm,y_mm,radius_mm,force_N,...)")
      ->check(CLI::ExistingFile);
  cmd->add_option("--out", job.out_path, "Calibration to write (JSON)");
  cmd->add_option("--contact-law", job.contact_law_path,
                  "Also fit the contact law (contact resistance against pressure, paper eq. 2) from measured "
                  "pairs (CSV: pressure_N_per_mm2,resistance_ohm)")
      ->check(CLI::ExistingFile);
  cmd->add_option("--method", a->method, "Reconstruction method the calibration is for")
      ->check(CLI::IsMember(method_names()))
      ->capture_default_str();
  cmd->add_option("--lambda2", job.options.lambda2, "lambda^2 (default: the method's)")
      ->check(checked_by(&PressCalibrationOptions::lambda2));
  cmd->add_option("--threshold", job.options.threshold_fraction, "Threshold fraction")
      ->check(checked_by(&PressCalibrationOptions::threshold_fraction))
      ->capture_default_str();
  cmd->add_flag("!--no-sheet", job.options.fit_sheet,
                "With --method fit: keep the nominal sensor (sheet, electrodes, drive) instead of fitting it from "
                "the presses");
  cmd->add_option("--sheet-terms", job.options.sensor.sheet_terms,
                  "With --method fit: the sheet's resistance field, 5 (quadratic) or 9 (cubic) terms")
      ->check(CLI::IsMember({5, 9}))
      ->capture_default_str();
  cmd->add_flag("!--no-electrodes", job.options.sensor.fit_electrode_positions,
                "With --method fit: keep the electrodes where the sensor file says (do not fit their positions)");
  cmd->add_flag("!--no-series-resistance", job.options.sensor.fit_series_resistance,
                "With --method fit: keep the sensor file's series resistances (do not fit them)");
  cmd->add_flag("!--no-drive", job.options.sensor.fit_drive_voltage,
                "With --method fit: keep the sensor file's drive voltage (do not fit it)");
  CaptureJob& capture = a->capture;
  cmd->add_option("--capture", capture.source_spec,
                  "Capture the calibration by hand from a live source (serial:PORT, file:REC, sim:calibration): lift "
                  "everything, press anywhere one finger at a time, put each known weight down; Ctrl-C keeps what was "
                  "captured");
  cmd->add_option("--capture-dir", capture.capture_dir,
                  "--capture: where reference.csv, frames.csv and presses.csv go (default: <out>_capture)");
  cmd->add_option("--presses", capture.presses, "--capture: finger presses (or until the sheet is covered)")
      ->check(positive_number())
      ->capture_default_str();
  cmd->add_option("--weights-N", capture.weights_N, "--capture: the known weights, put down one after another")
      ->delimiter(',')
      ->check(positive_number())
      ->capture_default_str();
  cmd->add_option("--weight-radius-mm", capture.weight_radius_mm, "--capture: each weight's flat foot's radius")
      ->check(positive_number())
      ->capture_default_str();
  cmd->add_option("--fps", capture.source.frames_per_s, "--capture from sim: the simulator's frame rate (0: unpaced)")
      ->check(non_negative_number())
      ->capture_default_str();
  cmd->add_option("--seed", capture.source.seed, "--capture from sim: the simulated person's and noise's seed");
  cmd->add_option("--cache", job.options.cache_dir,
                  "Operator cache folder (default: $EMIT_CACHE_DIR or ~/.cache/emit)");
  cmd->callback([a] { run_calibrate(*a); });
}

}  // namespace emit::cli
