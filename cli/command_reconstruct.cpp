// emit reconstruct: frames → contacts (JSON Lines) and, on request, a pressure map per frame.
#include <cmath>
#include <cstdio>

#include "commands.hpp"
#include "emit/core/errors.hpp"
#include "emit/core/threads.hpp"
#include "emit/jobs/reconstruct_job.hpp"
#include "emit/pipeline/pipeline.hpp"

namespace emit::cli {

namespace {

struct ReconstructArgs {
  ReconstructJob job;
  std::string method = "fit";
  bool no_cache = false;
};

void run_reconstruct(ReconstructArgs args) {
  ReconstructJob& job = args.job;
  job.method = parse_method(args.method);
  job.cache_dir = cache_dir_option(job.cache_dir, args.no_cache);
  job.threads = thread_count();
  const ReconstructReport r = run_reconstruct_job(job, stderr_progress(20));
  FILE* say = job.contacts_path == "-" ? stderr : stdout;  // stdout may carry the contacts
  std::fprintf(stderr, "model ready in %.2f s (%ld triangles, %d measurements%s)\n", r.model_seconds, r.triangles,
               r.measurements, r.operator_from_cache ? ", operator from the cache" : "");
  char lambda[48] = "";
  if (is_linear(job.method)) std::snprintf(lambda, sizeof lambda, " (lambda2 = %g)", r.lambda2);
  std::fprintf(say, "reconstructed %zu frames (%.0f frames/s%s) with the %s method%s; contacts in %s\n", r.frames,
               r.frames_per_s, job.images_dir.empty() ? "" : ", with images", args.method.c_str(), lambda,
               job.contacts_path.c_str());
  if (!job.mcap_path.empty())
    std::fprintf(say, "recorded frames, contacts and pressure images to %s (MCAP, ROS 2 messages)\n",
                 job.mcap_path.c_str());
  if (r.readings_masked > 0)
    std::fprintf(say, "readings: %ld masked in %ld of %zu frames (nan or inf, or clipped at the ADC's top code)\n",
                 r.readings_masked, r.frames_with_masked, r.frames);
  if (!r.calibrated)
    std::fprintf(say, "note: pressures are uncalibrated; run 'emit calibrate' for N/mm2 you can trust\n");
}

}  // namespace

void add_reconstruct_command(CLI::App& app) {
  auto a = std::make_shared<ReconstructArgs>();
  ReconstructJob& job = a->job;
  CLI::App* cmd = app.add_subcommand("reconstruct", "Reconstruct pressure images and contacts from frames");
  cmd->footer(
      "Example:\n  emit reconstruct --reference ref.csv --frames frames.csv --contacts contacts.jsonl --images out/");
  cmd->add_option("--sensor", job.sensor_path, "Sensor description (JSON); default: the built-in 60 mm sensor")
      ->check(CLI::ExistingFile);
  cmd->add_option("--reference", job.reference_path, "No-contact frames (CSV; several rows are averaged)")
      ->required()
      ->check(CLI::ExistingFile);
  cmd->add_option("--frames", job.frames_path, "Frames to reconstruct (CSV)")->required()->check(CLI::ExistingFile);
  cmd->add_option("--contacts", job.contacts_path, "Contacts out (JSON Lines, one object per frame); - for stdout")
      ->required();
  cmd->add_option("--tracks", job.tracks_path,
                  "Touches out as CSV, one row per touch per frame (time_s, id, phase, x_mm, y_mm, force_N, ...) for "
                  "a spreadsheet or pandas");
  cmd->add_option("--calibration", job.calibration_path, "Pressure calibration (JSON from 'emit calibrate')")
      ->check(CLI::ExistingFile);
  cmd->add_option("--method", a->method,
                  "fit (model-based contact fitting), paper (Tikhonov, Q = I), noser, or laplacian")
      ->check(CLI::IsMember(method_names()))
      ->capture_default_str();
  cmd->add_option("--lambda2", job.lambda2,
                  "Regularisation lambda^2 (default: chosen from the operator's spectrum, docs/physics.md)")
      ->check(checked_by(&PipelineOptions::lambda2));
  cmd->add_option("--threshold", job.threshold_fraction, "Threshold as a fraction of the image's maximum")
      ->check(checked_by(&FrameOptions::threshold_fraction))
      ->capture_default_str();
  cmd->add_option("--min-area-mm2", job.min_contact_area_mm2, "Drop contacts smaller than this")
      ->check(checked_by(&FrameOptions::min_contact_area_mm2));
  cmd->add_option(
         "--contact-radius-mm", job.contact_radius_mm,
         "fit and shapes: the indenter's radius, declared (a 3 mm stylus, a 10 mm finger pad): every contact's "
         "area held at pi R^2 (5 % on R) instead of the calibration indenter's, its force and pressure from it")
      ->check(checked_by(&FrameOptions::contact_radius_mm));
  cmd->add_option("--images", job.images_dir,
                  "Write a pressure map per frame (PNG, frame_000000.png on) into this folder");
  cmd->add_option("--pressure-range", job.images.max_pressure_N_per_mm2,
                  "With --images: the colour bar's top in N/mm2, the same for every frame so that frames compare "
                  "(default: each frame's own largest pressure)")
      ->type_name("MAX")
      ->check(checked_by(&PressureMapOptions::max_pressure_N_per_mm2));
  cmd->add_option("--image-width", job.images.width_px, "With --images: the pictures' width in pixels, 160 to 8192")
      ->type_name("PX")
      ->capture_default_str()
      ->check(checked_by("--image-width", [](double px) {
        PressureMapOptions o;
        if (px != std::floor(px) || std::abs(px) > 1e9) throw InvalidInput("must be a whole number of pixels");
        o.width_px = static_cast<int>(px);
        o.validate();
      }));
  cmd->add_option("--mcap", job.mcap_path,
                  "Also record the frames, contacts and pressure images as ROS 2 messages in an MCAP file (a bag)");
  cmd->add_option("--cache", job.cache_dir, "Operator cache folder (default: $EMIT_CACHE_DIR or ~/.cache/emit)");
  cmd->add_flag("--no-cache", a->no_cache, "Neither read nor write the operator cache");
  cmd->add_option("--fps", job.frames_per_s,
                  "The frames' rate: frame f is at f/FPS s, for the contacts' velocities and the MCAP's stamps")
      ->check(positive_number())
      ->capture_default_str();
  add_tracking_options(cmd, job.tracking);
  cmd->callback([a] { run_reconstruct(*a); });
}

}  // namespace emit::cli
