// emit export: a recording (emit live --record) into the files the other commands read: frames and
// a reference as CSV, contacts as JSON Lines, an MCAP bag. Parsing and printing only; the work is
// jobs/export_job.hpp.
#include <cstdio>

#include "commands.hpp"
#include "emit/jobs/export_job.hpp"
#include "emit/pipeline/pipeline.hpp"

namespace emit::cli {

namespace {

struct ExportArgs {
  ExportJob job;
  std::string method = "fit";
  bool no_cache = false;
};

void run_export(ExportArgs args) {
  ExportJob& job = args.job;
  job.method = parse_method(args.method);
  job.cache_dir = cache_dir_option(job.cache_dir, args.no_cache);
  const ExportReport r = run_export_job(job, stderr_progress(200));
  FILE* say = job.contacts_path == "-" ? stderr : stdout;  // stdout may carry the contacts
  std::fprintf(say, "exported %llu frames (%.1f s on the board's clock, %llu missed) in %.2f s\n",
               static_cast<unsigned long long>(r.frames), r.board_seconds,
               static_cast<unsigned long long>(r.frames_missed), r.seconds);
  if (!job.frames_path.empty()) std::fprintf(say, "frames: %s\n", job.frames_path.c_str());
  if (!job.reference_path.empty())
    std::fprintf(say, "reference: %s (the first %llu frames)\n", job.reference_path.c_str(),
                 static_cast<unsigned long long>(r.reference_frames));
  if (!job.contacts_path.empty())
    std::fprintf(say, "contacts: %s (the %s method, against the first %llu frames%s)\n", job.contacts_path.c_str(),
                 args.method.c_str(), static_cast<unsigned long long>(r.reference_frames),
                 r.calibrated ? ", calibrated" : "");
  if (!job.tracks_path.empty()) std::fprintf(say, "tracks: %s\n", job.tracks_path.c_str());
  if (!job.mcap_path.empty())
    std::fprintf(say, "recorded frames, contacts and pressure images to %s (MCAP, ROS 2 messages)\n",
                 job.mcap_path.c_str());
  if (job.reconstructs() && !r.calibrated)
    std::fprintf(say, "note: pressures are uncalibrated; run 'emit calibrate' for N/mm2 you can trust\n");
}

}  // namespace

void add_export_command(CLI::App& app) {
  auto a = std::make_shared<ExportArgs>();
  ExportJob& job = a->job;
  CLI::App* cmd =
      app.add_subcommand("export", "Turn a recording (emit live --record) into frames CSV, contacts and MCAP");
  cmd->footer(
      "Every frame goes to --frames; the first --reference-frames (the no-contact frames emit live captured its\n"
      "reference from) also to --reference. --contacts reconstructs every frame against them, as\n"
      "'emit reconstruct --reference R --frames F' would, with the board's times.\n"
      "Example:\n  emit export run.emitrec --frames f.csv --reference ref.csv --contacts c.jsonl");
  cmd->add_option("recording", job.recording_path, "The recording (.emitrec from emit live --record)")->required();
  cmd->add_option("--frames", job.frames_path, "Every frame out as CSV (what calibrate and reconstruct read)");
  cmd->add_option("--reference", job.reference_path, "The first --reference-frames frames out as CSV");
  cmd->add_option("--reference-frames", job.reference_frames,
                  "Frames at the recording's start that are the no-contact reference")
      ->check(positive_integer())
      ->capture_default_str();
  cmd->add_option("--contacts", job.contacts_path, "Contacts out (JSON Lines, one object per frame); - for stdout");
  cmd->add_option("--tracks", job.tracks_path,
                  "Touches out as CSV, one row per touch per frame (time_s on the board's clock, id, phase, x_mm, "
                  "...)");
  cmd->add_option("--mcap", job.mcap_path,
                  "Frames, contacts and pressure images out as ROS 2 messages in an MCAP file (a bag)");
  cmd->add_option("--sensor", job.sensor_path, "Sensor description (JSON); default: the built-in 60 mm sensor")
      ->check(CLI::ExistingFile);
  cmd->add_option("--calibration", job.calibration_path, "Pressure calibration (JSON from 'emit calibrate')")
      ->check(CLI::ExistingFile);
  cmd->add_option("--method", a->method,
                  "fit (model-based contact fitting), paper (Tikhonov, Q = I), noser, or laplacian")
      ->check(CLI::IsMember(method_names()))
      ->capture_default_str();
  cmd->add_option("--contact-radius-mm", job.contact_radius_mm,
                  "fit and shapes: the indenter's radius, declared: every contact's area held at pi R^2 (as "
                  "reconstruct)")
      ->check(checked_by(&FrameOptions::contact_radius_mm));
  cmd->add_option("--cache", job.cache_dir, "Operator cache folder (default: $EMIT_CACHE_DIR or ~/.cache/emit)");
  cmd->add_flag("--no-cache", a->no_cache, "Neither read nor write the operator cache");
  add_tracking_options(cmd, job.tracking);
  cmd->callback([a] { run_export(*a); });
}

}  // namespace emit::cli
