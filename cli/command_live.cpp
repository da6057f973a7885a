// emit live: frames from a source, reconstructed as they come, contacts out as JSON Lines and a
// viewer in the browser. Parsing and printing only; the session is jobs/live_session.hpp.
#include <array>
#include <atomic>
#include <csignal>
#include <cstdio>
#include <string>

#include "commands.hpp"
#include "emit/render/pressure_map.hpp"
#include "stop_on_signals.hpp"

namespace emit::cli {

namespace {

struct LiveArgs {
  LiveJob job;
  std::string method = "fit";
  bool no_cache = false;
};

/// ", made in X ms on its own thread" for a source that makes its frames (the twin), else nothing.
std::string making(const LiveStats& stats) {
  if (stats.source_make_s <= 0) return "";
  char text[64];
  std::snprintf(text, sizeof text, " (made in %.2f ms on its own thread)", 1e3 * stats.source_make_s);
  return text;
}

void print_summary(FILE* say, const LiveStats& stats) {
  std::fprintf(say,
               "live: %llu frames in %.1f s: %.1f frames/s; latency mean %.2f ms, p95 %.2f ms, max %.2f ms "
               "(from a frame's arrival to its contacts written and published); %llu missed (gaps in the "
               "source's frame numbers)\n",
               static_cast<unsigned long long>(stats.frames), stats.seconds, stats.frames_per_s,
               1e3 * stats.latency.mean_s(), 1e3 * stats.latency.quantile_s(0.95), 1e3 * stats.latency.max_s(),
               static_cast<unsigned long long>(stats.frames_missed));
  std::fprintf(say,
               "time per frame: source %.2f ms waited for%s, reconstruction %.2f ms, output %.2f ms (recording, "
               "writing and publishing); the bottleneck: %s\n",
               1e3 * stats.source_wait_s, making(stats).c_str(), 1e3 * stats.reconstruction_s, 1e3 * stats.output_s,
               stats.bottleneck());
  if (stats.readings_masked > 0)
    std::fprintf(say, "readings: %llu masked in %llu of %llu frames (not finite, or clipped at the ADC's top code)\n",
                 static_cast<unsigned long long>(stats.readings_masked),
                 static_cast<unsigned long long>(stats.frames_with_masked),
                 static_cast<unsigned long long>(stats.frames));
  std::fflush(say);
}

}  // namespace

void run_live(const LiveJob& job) {
  FILE* say = job.contacts_path == "-" ? stderr : stdout;  // stdout may carry the contacts
  LiveSession session(job, stderr_progress());
  std::fprintf(say, "source: %s\n", session.source_description().c_str());
  if (!job.serve.empty()) std::fprintf(say, "viewer: %s\n", session.viewer_url().c_str());
  if (!job.dds_prefix.empty())
    std::fprintf(say, "dds: publishing rt/%s/{contacts,frames,pressure,mesh} in domain %d\n",
                 job.dds_prefix.c_str() + (job.dds_prefix[0] == '/' ? 1 : 0), job.dds_domain);
  const std::string stopping = job.frames         ? "stopping after " + std::to_string(job.frames) + " frames"
                               : job.seconds != 0 ? "stopping after " + std::to_string(static_cast<int>(job.seconds)) +
                                                        " s (Ctrl-C stops sooner)"
                                                  : std::string("Ctrl-C stops");
  std::fprintf(say, "reconstructing with the %s method; %s\n", method_name(job.method), stopping.c_str());
  std::fflush(say);

  const StopOnSignals signals;
  LiveStats stats;
  try {
    stats = session.run(StopOnSignals::flag());
  } catch (const std::exception&) {
    // What the run did before it failed, and where what it wrote is; main() then prints the
    // failure itself, last, and exits 1.
    print_summary(say, session.stats());
    if (!session.kept_partial().empty()) {
      std::string kept;
      for (const std::string& path : session.kept_partial()) kept += (kept.empty() ? "" : ", ") + path;
      std::fprintf(stderr,
                   "emit: the run failed; what it wrote is kept in %s (the files it would have replaced are "
                   "untouched)\n",
                   kept.c_str());
    }
    throw;
  }
  if (stats.contacts_reader_left)
    std::fprintf(stderr, "emit: the reader of --contacts %s went away; stopped after %llu frames\n",
                 job.contacts_path.c_str(), static_cast<unsigned long long>(stats.frames));
  else if (stats.contacts_dropped > 0)
    std::fprintf(stderr, "emit: %llu contacts lines dropped while no one read --contacts %s\n",
                 static_cast<unsigned long long>(stats.contacts_dropped), job.contacts_path.c_str());
  print_summary(say, stats);
  if (!job.mcap_path.empty())
    std::fprintf(say, "recorded the reconstructed frames to %s (MCAP)\n", job.mcap_path.c_str());
  if (!job.record_path.empty())
    std::fprintf(say, "recorded %llu frames to %s (replay: emit live --source file:%s)\n",
                 static_cast<unsigned long long>(session.recorded_frames()), job.record_path.c_str(),
                 job.record_path.c_str());
  if (!session.calibrated())
    std::fprintf(say, "note: pressures are uncalibrated; run 'emit calibrate' for N/mm2 you can trust\n");
}

void add_live_command(CLI::App& app) {
  auto a = std::make_shared<LiveArgs>();
  LiveJob& job = a->job;
  CLI::App* cmd = app.add_subcommand("live", "Reconstruct frames as they come from a source; serve a live viewer");
  cmd->footer(
      "Examples:\n  emit live --source sim --serve 127.0.0.1:8080\n"
      "  emit live --source serial:/dev/ttyUSB0 --serve 127.0.0.1:8080 --record session.emitrec\n"
      "  emit live --source file:session.emitrec --contacts - --fps 0\n"
      "  emit live --source sim:fixed:20,40 --frames 100 --contacts contacts.jsonl");
  cmd->add_option("--source", job.source,
                  "sim (a finger moving in a figure-eight), sim:random, sim:fixed (at the middle), sim:fixed:X,Y[,F], "
                  "sim:fixed:OUTLINE (a flat "
                  "punch held, as simulate --press takes it: bar:x,y,L,W,angle,F, ellipse:…), file:REC (a recording), "
                  "or serial:PORT[@BAUD] (the board; 921600 baud by default)")
      ->capture_default_str();
  cmd->add_option("--record", job.record_path, "Record every frame the source gives to this file (replay with file:)");
  cmd->add_option("--mcap", job.mcap_path,
                  "Record each reconstructed frame, its contacts and pressure image as ROS 2 messages in an MCAP file");
  cmd->add_option("--dds", job.dds_prefix,
                  "Publish on DDS as ROS 2 does: topics rt/PREFIX/contacts, /frames, /pressure, /mesh (a ROS 2 node "
                  "with the Cyclone DDS RMW subscribes to /PREFIX/contacts)");
  cmd->add_option("--dds-domain", job.dds_domain, "The DDS domain (ROS_DOMAIN_ID), 0 to 232")->capture_default_str();
  cmd->add_option("--frame-id", job.frame_id,
                  "The ROS frame of the sheet in --dds and --mcap messages' headers; place it in your robot with a "
                  "static transform (README, \"ROS 2\")")
      ->capture_default_str();
  cmd->add_option("--serve", job.serve, "Serve the viewer at HOST:PORT (e.g. 127.0.0.1:8080; port 0 picks a free one)");
  cmd->add_option("--pressure-range", job.pressure_range_N_per_mm2,
                  "With --serve: the viewer's colour bar top in N/mm2, fixed (default: the largest pressure seen so "
                  "far)")
      ->type_name("MAX")
      ->check(checked_by(&PressureMapOptions::max_pressure_N_per_mm2));
  cmd->add_option("--contacts", job.contacts_path,
                  "Contacts out as JSON Lines: a file (FILE.partial until the end), a FIFO (readers may come and go), "
                  "or - for stdout (the run ends when its reader goes)");
  cmd->add_option("--tracks", job.tracks_path,
                  "Touches out as CSV, one row per touch per frame (time_s, id, phase, x_mm, y_mm, force_N, ...) for "
                  "a spreadsheet or pandas (FILE.partial until the end)");
  cmd->add_option("--method", a->method,
                  "fit (model-based contact fitting), paper (Tikhonov, Q = I), noser, or laplacian")
      ->check(CLI::IsMember(method_names()))
      ->capture_default_str();
  cmd->add_option(
         "--contact-radius-mm", job.contact_radius_mm,
         "fit and shapes: the indenter's radius, declared (a 3 mm stylus, a 10 mm finger pad): every contact's "
         "area held at pi R^2 (5 % on R) instead of the calibration indenter's, its force and pressure from it")
      ->check(checked_by(&FrameOptions::contact_radius_mm));
  cmd->add_option("--sensor", job.sensor_path, "Sensor description (JSON); default: the built-in 60 mm sensor")
      ->check(CLI::ExistingFile);
  cmd->add_option("--calibration", job.calibration_path, "Pressure calibration (JSON from 'emit calibrate')")
      ->check(CLI::ExistingFile);
  cmd->add_option("--frames", job.frames, "Stop after this many reconstructed frames (default: run until Ctrl-C)")
      ->check(positive_number());
  cmd->add_option("--seconds", job.seconds, "Stop after this many seconds (default: run until Ctrl-C)")
      ->check(positive_number());
  cmd->add_option("--fps", job.frames_per_s,
                  "The simulator's frame rate; 0 replays a recording as fast as it goes (otherwise at its own pace)")
      ->check(non_negative_number())
      ->capture_default_str();
  cmd->add_option("--reconnect-s", job.reconnect_s,
                  "serial: how long a port that went away (a pulled cable) is retried, every 0.5 s, before the run "
                  "fails with its error")
      ->check(positive_number())
      ->capture_default_str();
  cmd->add_flag("--loop", job.loop,
                "Replay the recording (file:REC) again from its start at its end, frame numbers and board time "
                "going on, until Ctrl-C, --frames or --seconds");
  cmd->add_option("--cache", job.cache_dir, "Operator cache folder (default: $EMIT_CACHE_DIR or ~/.cache/emit)");
  cmd->add_flag("--no-cache", a->no_cache, "Neither read nor write the operator cache");
  add_tracking_options(cmd, job.tracking);
  cmd->callback([a] {
    LiveJob job = a->job;
    job.method = parse_method(a->method);
    job.cache_dir = cache_dir_option(job.cache_dir, a->no_cache);
    run_live(job);
  });
}

}  // namespace emit::cli
