// emit demo: the main job on the built-in sensor, end to end. The digital twin of the default
// 60 x 60 mm sheet stands in for a real one: it records a reference frame and presses of known
// force (the calibration), then a few presses; emit calibrates, reconstructs them by contact
// fitting and by the paper's method, prints what it found beside the truth, and draws each frame.
// Then it goes live: `emit live --source sim` with that calibration, a finger moving over the
// sheet, and the viewer served in the browser.
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>

#include "commands.hpp"
#include "emit/fit/fit_model.hpp"
#include "emit/io/atomic_file.hpp"
#include "emit/io/calibration_json.hpp"
#include "emit/io/contacts_jsonl.hpp"
#include "emit/io/frames_csv.hpp"
#include "emit/io/presses_csv.hpp"
#include "emit/mesh/element_to_node.hpp"
#include "emit/reconstruct/calibration.hpp"
#include "emit/reconstruct/operator_cache.hpp"
#include "emit/render/field_image.hpp"
#include "emit/sensor/sensor_json.hpp"
#include "emit/twin/press_scripts.hpp"
#include "emit/twin/twin.hpp"

namespace emit::cli {

namespace {

double seconds_since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

/// Each true press beside the fitted contact nearest to it and the paper method's strongest
/// contact; fitted contacts near no press are printed as false ones.
void print_found(std::size_t f, const std::vector<Press>& presses, const std::vector<Contact>& fitted,
                 const std::vector<Contact>& paper) {
  std::vector<bool> used(fitted.size(), false);
  for (std::size_t i = 0; i < presses.size(); ++i) {
    const Press& p = presses[i];
    std::printf("  %5zu  %5.1f %5.1f %6.1f", f, p.x_mm, p.y_mm, p.force_N);
    std::size_t nearest = fitted.size();
    for (std::size_t k = 0; k < fitted.size(); ++k)
      if (!used[k] && (nearest == fitted.size() || std::hypot(fitted[k].x_mm - p.x_mm, fitted[k].y_mm - p.y_mm) <
                                                       std::hypot(fitted[nearest].x_mm - p.x_mm, fitted[nearest].y_mm - p.y_mm)))
        nearest = k;
    if (nearest < fitted.size()) {
      used[nearest] = true;
      std::printf("   %6.2f %6.2f %6.1f", fitted[nearest].x_mm, fitted[nearest].y_mm, fitted[nearest].force_N);
    } else {
      std::printf("   %20s", "(not found)");
    }
    if (i == 0 && !paper.empty()) std::printf("   %6.1f %6.1f", paper[0].x_mm, paper[0].y_mm);
    std::printf("\n");
  }
  for (std::size_t k = 0; k < fitted.size(); ++k)
    if (!used[k])
      std::printf("  %5zu  %19s   %6.2f %6.2f %6.1f (a false contact)\n", f, "", fitted[k].x_mm, fitted[k].y_mm,
                  fitted[k].force_N);
}

struct DemoArgs {
  std::string out_dir = "emit-demo", serve = "127.0.0.1:8080";
  double live_seconds = 60;
};

/// Calibrates on the twin and reconstructs a few presses; writes the calibration to
/// `calibration_path` for the live part.
void calibrate_and_reconstruct(const std::string& out_dir, const std::string& calibration_path) {
  const Sensor sensor = default_sensor();
  const PressSequence sequence = {
      {{30, 30, 5, 10}},                    // centre, 5 mm indenter, 10 N
      {{12, 48, 5, 5}},                     // near the top-left corner, lighter
      {{20, 20, 4, 8}, {42, 40, 6, 15}},    // two fingers
      {{45, 15, 3, 2}},                     // a small, light press
  };
  std::printf("emit demo: %s (%d electrodes, %.1f V drive, %.0f ohm/sq); its digital twin stands in for the sheet\n",
              sensor.name.c_str(), sensor.electrode_count(), sensor.drive_voltage_V, sensor.sheet_resistance_ohm_per_sq);
  auto start = std::chrono::steady_clock::now();
  Twin twin(sensor);
  const Frame reference = twin.frame({});
  PressStyle style;  // 5 mm indenter, 2 to 39 N: 0.025 to 0.5 N/mm², the paper's range
  style.min_force_N = 2, style.max_force_N = 39, style.seed = 11;
  const PressSequence calibration_presses = random_script(sensor, 20, style);
  std::vector<Frame> calibration_frames, frames;
  for (const auto& presses : calibration_presses) calibration_frames.push_back(twin.frame(presses));
  for (const auto& presses : sequence) frames.push_back(twin.frame(presses));
  std::printf("twin: a reference frame, 20 presses of known force, %zu frames to reconstruct (%.1f s)\n",
              sequence.size(), seconds_since(start));

  start = std::chrono::steady_clock::now();
  const auto say = [](const std::string& stage) { std::fprintf(stderr, "%s ...\n", stage.c_str()); };
  const ReconstructionModel model = build_reconstruction_model(sensor, method_options("paper"), default_cache_dir(), {}, say);
  const FitModel fit_model = build_fit_model(sensor, nullptr, say);
  std::printf("models: paper operator (%lld triangles), contact fitting (%lld nodes) in %.1f s\n",
              static_cast<long long>(model.mesh.triangle_count()), static_cast<long long>(fit_model.mesh.node_count()),
              seconds_since(start));

  Reconstructor paper(model, PressureCalibration::uncalibrated(sensor));
  paper.set_reference(reference);
  ContactFitter uncalibrated(sensor, fit_model.mesh, fit_model.green, model.measurements);
  Reconstructor calibrating(model, PressureCalibration::uncalibrated(sensor));
  calibrating.use_fitter(&uncalibrated);
  calibrating.set_reference(reference);
  Sensor calibrated = sensor;
  std::vector<double> calibration_pressures;
  for (const auto& presses : calibration_presses) calibration_pressures.push_back(presses[0].pressure_N_per_mm2());
  calibrated.contact = calibrate_fitted_contact_law(calibrating, calibration_frames, calibration_pressures, sensor.contact).law;
  std::printf("calibrated on the 20 presses: the contact law as the fit sees it, alpha = %.4g ohm mm2, gamma = %.3f\n",
              calibrated.contact.alpha_ohm_mm2, calibrated.contact.gamma);
  ContactFitter fitter(calibrated, fit_model.mesh, fit_model.green, model.measurements);
  PressureCalibration calibration;  // contacts reported with the calibration presses' indenter
  calibration.calibrated = true;
  calibration.fitted_contact_law = calibrated.contact;
  calibration.indenter_radius_mm = style.radius_mm;
  Reconstructor fitting(model, calibration);
  fitting.use_fitter(&fitter);
  fitting.set_reference(reference);

  std::printf("\n  frame   true x     y  force N   fit x      y  force N   paper x    y\n");
  AtomicFile contacts_file(out_dir + "/contacts.jsonl");
  for (std::size_t f = 0; f < frames.size(); ++f) {
    const std::vector<Contact> found = fitting.process(frames[f]);
    const std::vector<Contact> linear = paper.process(frames[f]);
    print_found(f, sequence[f], found, linear);
    write_contacts_line(contacts_file.stream(), static_cast<long>(f), found, 1e3 * fitting.fit_result()->rms_misfit_V);
    std::vector<Circle> outlines;
    for (const Press& p : sequence[f]) outlines.push_back({Vector2(p.x_mm, p.y_mm), p.radius_mm});
    FieldImageOptions image;
    image.title = "frame " + std::to_string(f) + ": pressure by contact fitting (circles: the true presses)";
    image.unit = "N/mm2";
    image.min_value = 0;
    write_png(render_field(fitting.mesh(), element_to_node(fitting.mesh(), fitting.pressure()), outlines, image),
              out_dir + "/frame_" + std::to_string(f) + ".png");
  }
  contacts_file.commit();
  write_frames_csv(out_dir + "/frames.csv", frames);
  write_presses_csv(out_dir + "/presses.csv", sequence);
  write_calibration(calibration_path, calibration);
  std::printf("\nwrote %s/frames.csv, presses.csv, contacts.jsonl, calibration.json and %zu pressure maps frame_*.png\n",
              out_dir.c_str(), sequence.size());
}

void run_demo(const DemoArgs& args) {
  std::filesystem::create_directories(args.out_dir);
  const std::string calibration_path = args.out_dir + "/calibration.json";
  calibrate_and_reconstruct(args.out_dir, calibration_path);
  std::printf("\nlive: the twin streams a finger moving over the sheet; watch it in a browser at the address below\n");
  LiveArgs live;
  live.source = "sim";
  live.serve = args.serve;
  live.calibration_path = calibration_path;
  live.contacts_path = args.out_dir + "/live_contacts.jsonl";
  live.record_path = args.out_dir + "/live.emitrec";
  live.seconds = args.live_seconds;
  run_live(live);
  std::printf("next: emit live --source serial:/dev/ttyUSB0 --serve %s (your board), emit eval (accuracy against the\n"
              "paper), emit reconstruct --help (your own frames)\n", args.serve.c_str());
}

}  // namespace

void add_demo_command(CLI::App& app) {
  auto a = std::make_shared<DemoArgs>();
  CLI::App* cmd = app.add_subcommand(
      "demo", "Simulate presses on the built-in 60 mm sensor, calibrate, reconstruct and draw them, then go live in the browser");
  cmd->add_option("--out", a->out_dir, "Folder for the frames, presses, contacts, images and the live recording")
      ->capture_default_str();
  cmd->add_option("--serve", a->serve, "Where the live viewer is served (HOST:PORT; port 0 picks a free one)")
      ->capture_default_str();
  cmd->add_option("--seconds", a->live_seconds, "How long the live part runs (Ctrl-C stops sooner)")
      ->check(CLI::PositiveNumber)
      ->capture_default_str();
  cmd->callback([a] { run_demo(*a); });
}

}  // namespace emit::cli
