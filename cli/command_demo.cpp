// emit demo: the main job on the built-in sensor, end to end (jobs/demo_job.hpp): its digital
// twin stands in for a real sheet; emit calibrates, reconstructs a few presses by contact fitting
// and by the paper's method, prints what it found beside the truth and draws each frame. Then it
// goes live (`emit live --source sim` with that calibration) with the viewer in the browser.
#include <cmath>
#include <cstdio>

#include "commands.hpp"
#include "emit/jobs/demo_job.hpp"
#include "emit/model/operator_cache.hpp"

namespace emit::cli {

namespace {

/// Each true press beside the fitted contact nearest to it and the paper method's strongest
/// contact; fitted contacts near no press are printed as false ones.
void print_found(std::size_t f, const std::vector<Press>& presses, const std::vector<Contact>& fitted,
                 const std::vector<Contact>& paper) {
  std::vector<bool> used(fitted.size(), false);
  const auto distance = [](const Contact& c, const Press& p) { return std::hypot(c.x_mm - p.x_mm, c.y_mm - p.y_mm); };
  for (std::size_t i = 0; i < presses.size(); ++i) {
    const Press& p = presses[i];
    std::printf("  %5zu  %5.1f %5.1f %6.1f", f, p.x_mm, p.y_mm, p.force_N);
    std::size_t nearest = fitted.size();
    for (std::size_t k = 0; k < fitted.size(); ++k)
      if (!used[k] && (nearest == fitted.size() || distance(fitted[k], p) < distance(fitted[nearest], p))) nearest = k;
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

void run_demo(const DemoArgs& args) {
  const DemoReport r = run_demo_reconstruction(args.out_dir, default_cache_dir(), stderr_progress());
  std::printf("emit demo: %s (%d electrodes, %.1f V drive, %.0f ohm/sq); its digital twin stands in for the sheet\n",
              r.sensor.name.c_str(), r.sensor.electrode_count(), r.sensor.drive_voltage_V,
              r.sensor.sheet_resistance_ohm_per_sq);
  std::printf("twin: a reference frame, %zu presses of known force, %zu frames to reconstruct (%.1f s)\n",
              r.calibration_presses, r.presses.size(), r.twin_seconds);
  std::printf("models: paper operator (%ld triangles), contact fitting (%ld nodes) in %.1f s\n", r.triangles,
              r.fit_mesh_nodes, r.model_seconds);
  std::printf("calibrated on the %zu presses: the contact law as the fit sees it, alpha = %.4g ohm mm2, gamma = %.3f\n",
              r.calibration_presses, r.calibration.contact_law.alpha_ohm_mm2, r.calibration.contact_law.gamma);
  std::printf("\n  frame   true x     y  force N   fit x      y  force N   paper x    y\n");
  for (std::size_t f = 0; f < r.presses.size(); ++f) print_found(f, r.presses[f], r.fitted[f], r.paper[f]);
  std::
      printf("\nwrote %s/frames.csv, presses.csv, contacts.jsonl, calibration.json and %zu pressure maps frame_*.png\n",
             args.out_dir.c_str(), r.presses.size());

  std::printf("\nlive: the twin streams a finger moving over the sheet; watch it in a browser at the address below\n");
  LiveJob live;
  live.source = "sim";
  live.serve = args.serve;
  live.calibration_path = r.calibration_path;
  live.contacts_path = args.out_dir + "/live_contacts.jsonl";
  live.record_path = args.out_dir + "/live.emitrec";
  live.seconds = args.live_seconds;
  live.cache_dir = default_cache_dir();
  run_live(live);
  std::printf(
      "next: emit live --source serial:/dev/ttyUSB0 --serve %s (your board), emit eval (accuracy against the\n"
      "paper), emit reconstruct --help (your own frames)\n",
      args.serve.c_str());
}

}  // namespace

void add_demo_command(CLI::App& app) {
  auto a = std::make_shared<DemoArgs>();
  CLI::App* cmd = app.add_subcommand("demo",
                                     "Simulate presses on the built-in 60 mm sensor, calibrate, reconstruct and draw "
                                     "them, then go live in the browser");
  cmd->footer("Example:\n  emit demo --out emit-demo --seconds 30");
  cmd->add_option("--out", a->out_dir, "Folder for the frames, presses, contacts, images and the live recording")
      ->capture_default_str();
  cmd->add_option("--serve", a->serve, "Where the live viewer is served (HOST:PORT; port 0 picks a free one)")
      ->capture_default_str();
  cmd->add_option("--seconds", a->live_seconds, "How long the live part runs (Ctrl-C stops sooner)")
      ->check(positive_number())
      ->capture_default_str();
  cmd->callback([a] { run_demo(*a); });
}

}  // namespace emit::cli
