// emit live: frames from a source, reconstructed as they come, contacts out as JSON Lines and a
// viewer in the browser. Parsing, wiring and printing only; the work is in emit/live/.
#include <atomic>
#include <csignal>
#include <cstdio>
#include <fstream>
#include <iostream>
#include <optional>

#include "commands.hpp"
#include "emit/acquire/frame_source.hpp"
#include "emit/errors.hpp"
#include "emit/io/calibration_json.hpp"
#include "emit/live/live_loop.hpp"
#include "emit/live/live_server.hpp"
#include "emit/reconstruct/operator_cache.hpp"

namespace emit::cli {

namespace {

std::atomic<bool> stop_requested{false};  // set by SIGINT/SIGTERM: the loop finishes its frame and returns
extern "C" void request_stop(int) { stop_requested = true; }

/// SIGINT and SIGTERM stop the loop gracefully while this lives; the old handlers come back after.
class StopOnSignals {
 public:
  StopOnSignals() {
    struct sigaction action {};
    action.sa_handler = request_stop;
    sigemptyset(&action.sa_mask);
    sigaction(SIGINT, &action, &old_int_);
    sigaction(SIGTERM, &action, &old_term_);
  }
  ~StopOnSignals() {
    sigaction(SIGINT, &old_int_, nullptr);
    sigaction(SIGTERM, &old_term_, nullptr);
  }

 private:
  struct sigaction old_int_ {}, old_term_ {};
};

}  // namespace

void run_live(const LiveArgs& args) {
  const Sensor sensor = sensor_from_option(args.sensor_path);
  const PressureCalibration calibration =
      args.calibration_path.empty() ? PressureCalibration::uncalibrated(sensor) : load_calibration(args.calibration_path);
  check_calibration_for_method(calibration, args.method, args.calibration_path);
  std::ofstream contacts_file;
  std::ostream* contacts = nullptr;
  if (args.contacts_path == "-") {
    contacts = &std::cout;
  } else if (!args.contacts_path.empty()) {
    contacts_file.open(args.contacts_path);
    if (!contacts_file) throw IoError(args.contacts_path + ": cannot write (does the folder exist?)");
    contacts = &contacts_file;
  }
  FILE* say = args.contacts_path == "-" ? stderr : stdout;  // stdout may carry the contacts

  SourceOptions source_options;
  source_options.frames_per_s = args.frames_per_s;
  const auto source = open_source(args.source, sensor, source_options);
  SetupOptions setup_options;
  setup_options.method = args.method;
  setup_options.cache_dir = args.no_cache ? "" : (args.cache_dir.empty() ? default_cache_dir() : args.cache_dir);
  ReconstructionSetup setup(sensor, calibration, setup_options,
                            [](const std::string& stage) { std::fprintf(stderr, "%s ...\n", stage.c_str()); });
  LiveOptions live_options;
  live_options.max_frames = args.frames;
  live_options.max_seconds = args.seconds;
  LiveLoop loop(*source, setup, live_options);
  loop.write_contacts_to(contacts);
  std::optional<Recorder> recorder;
  if (!args.record_path.empty()) loop.record_to(&recorder.emplace(args.record_path, sensor));
  std::optional<LiveServer> server;
  if (!args.serve.empty()) {
    server.emplace(args.serve, setup.model().mesh, sensor.name, [&loop](const std::string& command) { loop.command(command); });
    loop.add_publisher(&*server);
  }
  std::fprintf(say, "source: %s\n", source->description().c_str());
  if (server) std::fprintf(say, "viewer: %s\n", server->url().c_str());
  const std::string stopping = args.frames    ? "stopping after " + std::to_string(args.frames) + " frames"
                               : args.seconds ? "stopping after " + std::to_string(static_cast<int>(args.seconds)) + " s (Ctrl-C stops sooner)"
                                              : std::string("Ctrl-C stops");
  std::fprintf(say, "reconstructing with the %s method; %s\n", args.method.c_str(), stopping.c_str());
  std::fflush(say);

  stop_requested = false;
  const StopOnSignals signals;
  const LiveStats stats = loop.run(stop_requested);
  std::fprintf(say, "live: %llu frames in %.1f s: %.1f frames/s; latency mean %.2f ms, p95 %.2f ms, max %.2f ms "
                    "(from a frame's arrival to its contacts written and published)\n",
               static_cast<unsigned long long>(stats.frames), stats.seconds, stats.frames_per_s,
               1e3 * stats.latency.mean_s(), 1e3 * stats.latency.quantile_s(0.95), 1e3 * stats.latency.max_s());
  if (recorder) {
    recorder->close();
    std::fprintf(say, "recorded %llu frames to %s (replay: emit live --source file:%s)\n",
                 static_cast<unsigned long long>(recorder->frames()), recorder->path().c_str(), recorder->path().c_str());
  }
  if (!calibration.calibrated) std::fprintf(say, "note: pressures are uncalibrated; run 'emit calibrate' for N/mm2 you can trust\n");
}

void add_live_command(CLI::App& app) {
  auto a = std::make_shared<LiveArgs>();
  CLI::App* cmd = app.add_subcommand("live", "Reconstruct frames as they come from a source; serve a live viewer");
  cmd->footer("Examples:\n  emit live --source sim --serve 127.0.0.1:8080\n"
              "  emit live --source serial:/dev/ttyUSB0 --serve 127.0.0.1:8080 --record session.emitrec\n"
              "  emit live --source file:session.emitrec --contacts - --fps 0\n"
              "  emit live --source sim:fixed:20,40 --frames 100 --contacts contacts.jsonl");
  cmd->add_option("--source", a->source,
                  "sim (a finger moving in a figure-eight), sim:random, sim:fixed:X,Y[,F], file:REC (a recording), "
                  "or serial:PORT[@BAUD] (the board; 921600 baud by default)")
      ->capture_default_str();
  cmd->add_option("--record", a->record_path, "Record every frame the source gives to this file (replay with file:)");
  cmd->add_option("--serve", a->serve, "Serve the viewer at HOST:PORT (e.g. 127.0.0.1:8080; port 0 picks a free one)");
  cmd->add_option("--contacts", a->contacts_path, "Contacts out as JSON Lines: a file, or - for stdout");
  cmd->add_option("--method", a->method, "fit (model-based contact fitting) or paper (Tikhonov, Q = I)")
      ->check(CLI::IsMember({"fit", "paper"}))
      ->capture_default_str();
  cmd->add_option("--sensor", a->sensor_path, "Sensor description (JSON); default: the built-in 60 mm sensor")
      ->check(CLI::ExistingFile);
  cmd->add_option("--calibration", a->calibration_path, "Pressure calibration (JSON from 'emit calibrate')")
      ->check(CLI::ExistingFile);
  cmd->add_option("--frames", a->frames, "Stop after this many reconstructed frames (default: run until Ctrl-C)")
      ->check(CLI::PositiveNumber);
  cmd->add_option("--seconds", a->seconds, "Stop after this many seconds (default: run until Ctrl-C)")
      ->check(CLI::PositiveNumber);
  cmd->add_option("--fps", a->frames_per_s, "The simulator's frame rate; 0 replays a recording as fast as it goes (otherwise at its own pace)")
      ->check(CLI::NonNegativeNumber)
      ->capture_default_str();
  cmd->add_option("--cache", a->cache_dir, "Operator cache folder (default: $EMIT_CACHE_DIR or ~/.cache/emit)");
  cmd->add_flag("--no-cache", a->no_cache, "Neither read nor write the operator cache");
  cmd->callback([a] { run_live(*a); });
}

}  // namespace emit::cli
