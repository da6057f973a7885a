#include "emit/jobs/export_job.hpp"

#include <chrono>
#include <cmath>
#include <optional>

#include "emit/acquire/electrode_health.hpp"
#include "emit/acquire/file_source.hpp"
#include "emit/core/errors.hpp"
#include "emit/core/option_check.hpp"
#include "emit/core/output_paths.hpp"
#include "emit/frame/reference.hpp"
#include "emit/io/contacts_jsonl.hpp"
#include "emit/io/frames_csv.hpp"
#include "emit/io/tactile_mcap.hpp"
#include "emit/io/tracks_csv.hpp"
#include "emit/mesh/sheet_file.hpp"
#include "emit/pipeline/pipeline.hpp"
#include "reconstruct_inputs.hpp"

namespace emit {

void ExportJob::validate() const {
  if (frames_path.empty() && reference_path.empty() && !reconstructs())
    throw InvalidInput("nothing to export: give --frames, --reference, --contacts, --tracks or --mcap");
  option_check::at_least("ExportJob", "reference_frames", reference_frames, 1);
  if (!calibration_path.empty() && !reconstructs())
    throw InvalidInput("--calibration " + calibration_path +
                       ": only --contacts, --tracks and --mcap reconstruct frames, and none is given");
  tracking.validate();
}

namespace {

/// What a first pass over the recording finds before anything is built or written: how many
/// frames it holds whole and readable, what stopped it short (a cut, a corrupt packet), the
/// reference's frames and, for a reconstruction, the dead electrodes.
struct RecordingSurvey {
  std::uint64_t frames = 0;
  std::string failure;  ///< the IoError that ends the recording early; empty: it ends whole
  std::vector<Frame> reference;
  std::vector<DeadElectrode> dead;
  double first_board_s = 0, last_board_s = 0;
  std::uint64_t missed = 0;
  std::uint64_t start_unix_us = 0;  ///< when recording started (its header)
};

RecordingSurvey survey_recording(const ExportJob& job, const Sensor& sensor) {
  FileSource source(job.recording_path, sensor, /*as_fast_as_possible=*/true);
  const int N = sensor.electrode_count();
  ElectrodeHealthTally health(N, sensor.adc);
  RecordingSurvey survey;
  survey.start_unix_us = source.header().start_unix_us;
  SourceFrame frame;
  std::uint64_t last_sequence = 0;
  try {
    while (!source.finished()) {                         // a whole recording: finished as its last frame is handed out
      source.next(frame, std::chrono::milliseconds(0));  // as fast as possible: never waits
      if (job.reconstructs()) {
        check_readings_in_range(frame.volts, sensor.adc,
                                job.recording_path + ": frame " + std::to_string(survey.frames));
        health.add(frame.volts);
      }
      if (survey.reference.size() < static_cast<std::size_t>(job.reference_frames))
        survey.reference.push_back(frame.volts);
      if (survey.frames == 0) survey.first_board_s = frame.board_time_s;
      // The board's 32-bit numbers: a step of more than one is a gap; one at or behind the last, a restart.
      const std::uint32_t gap = static_cast<std::uint32_t>(frame.sequence - last_sequence) - 1u;
      if (survey.frames > 0 && gap < (1u << 31)) survey.missed += gap;
      last_sequence = frame.sequence;
      survey.last_board_s = frame.board_time_s;
      ++survey.frames;
    }
  } catch (const IoError& e) {
    // "end of recording" of one without frames is its end; a cut or corrupt packet is a failure,
    // and the frames before it are exported.
    if (!source.finished()) survey.failure = e.what();
  }
  if (survey.frames == 0)
    throw InvalidInput(job.recording_path + ": no frames to export" +
                       (survey.failure.empty() ? " (an empty recording)" : " (" + survey.failure + ")"));
  const bool needs_reference = !job.reference_path.empty() || job.reconstructs();
  if (needs_reference && survey.reference.size() < static_cast<std::size_t>(job.reference_frames))
    throw InvalidInput(job.recording_path + ": " + std::to_string(survey.frames) +
                       " frames, fewer than the reference's " + std::to_string(job.reference_frames) +
                       " (--reference-frames)");
  if (job.reconstructs()) survey.dead = health.dead();
  return survey;
}

}  // namespace

ExportReport run_export_job(const ExportJob& job, const Progress& progress) {
  job.validate();
  // Every output opened before any input is read: one that cannot be opened touches none. Each
  // grows as PATH.partial, renamed when the whole recording is in it (the file's comment).
  auto outputs =
      open_outputs({{"the recording", job.recording_path},
                    {"--sensor", job.sensor_path},
                    {"--calibration", job.calibration_path}},
                   {OutputRequest{{"--frames", job.frames_path}, {.partial = true}},
                    OutputRequest{{"--reference", job.reference_path}, {.partial = true}},
                    OutputRequest{{"--contacts", job.contacts_path}, {.partial = true, .standard_output = true}},
                    OutputRequest{{"--tracks", job.tracks_path}, {.partial = true}},
                    OutputRequest{{"--mcap", job.mcap_path}, {.partial = true}}});
  auto& [frames_file, reference_file, contacts_file, tracks_file, mcap_file] = outputs;
  const auto start = std::chrono::steady_clock::now();
  FrameOptions frame_options;
  frame_options.contact_radius_mm = job.contact_radius_mm;
  if (job.reconstructs()) check_frame_options(job.method, frame_options);
  const Sensor sensor = load_sheet_sensor(job.sensor_path);
  if (job.reconstructs()) require_emit_protocol(sensor, job.sensor_path);
  const std::optional<Calibration> calibration =
      detail::load_job_calibration(job.calibration_path, job.method, progress);

  // The recording read through once, before anything is built or written.
  const RecordingSurvey survey = survey_recording(job, sensor);
  ExportReport report;
  report.frames = survey.frames;
  report.board_seconds = survey.last_board_s - survey.first_board_s;
  report.frames_missed = survey.missed;
  if (reference_file.given()) {
    write_frames_csv(reference_file.stream(), survey.reference);
    report.reference_frames = survey.reference.size();
  }

  std::optional<Pipeline> pipeline;
  std::optional<Reconstructor> reconstructor;
  std::optional<ContactTracker> tracker;
  std::optional<TactileMcap> mcap;
  std::uint64_t start_ns = 0;
  if (job.reconstructs()) {
    const int N = sensor.electrode_count();
    PipelineOptions options{job.method, 0, job.cache_dir, {}};
    options.excluded = detail::leave_out_dead(survey.dead, N, progress);
    report.dead_electrodes = options.excluded;
    pipeline.emplace(sensor, options, calibration, progress.stage, job.calibration_path);
    report.calibrated = pipeline->calibrated();
    report.triangles = static_cast<long>(pipeline->model().mesh.triangle_count());
    reconstructor.emplace(pipeline->reconstructor(frame_options));
    reconstructor->set_reference(average_reference(survey.reference));  // as `--reference R.csv` is read
    report.reference_frames = survey.reference.size();
    tracker.emplace(job.tracking, 64, pipeline->model().surface);
    if (tracks_file.given()) write_tracks_header(tracks_file.stream());
    start_ns = survey.start_unix_us * 1000;
    if (mcap_file.given()) mcap.emplace(std::move(mcap_file), sensor.name, pipeline->model().mesh, start_ns);
  }

  FileSource source(job.recording_path, sensor, /*as_fast_as_possible=*/true);
  SourceFrame frame;
  std::vector<Frame> one(1);  // write_frames_csv's one frame, its storage reused
  for (std::uint64_t f = 0; f < survey.frames; ++f) {
    source.next(frame, std::chrono::milliseconds(0));
    if (frames_file.given()) {
      one[0] = frame.volts;
      write_frames_csv(frames_file.stream(), one);
    }
    if (reconstructor) {
      const std::vector<Contact>& found = reconstructor->process(frame.volts);
      const std::vector<Contact>& contacts = tracker->update(found, frame.board_time_s);
      const FitResult* fitted = reconstructor->fit_result();
      if (contacts_file.given())
        write_contacts_line(contacts_file.stream(), static_cast<long>(f), contacts,
                            fitted != nullptr ? 1e3 * fitted->rms_misfit_V : -1, FrameTimes{frame.board_time_s},
                            &tracker->ended());
      if (tracks_file.given())
        write_tracks_rows(tracks_file.stream(), frame.board_time_s, f, contacts, &tracker->ended());
      if (mcap) {
        const double since_start_s = std::max(frame.board_time_s - survey.first_board_s, 0.0);
        mcap->write(f, start_ns + static_cast<std::uint64_t>(std::llround(1e9 * since_start_s)),
                    frame_view(frame.volts), contacts, reconstructor->pressure(), frame.board_time_s,
                    &tracker->ended());
      }
    }
    progress.step("exporting frame", static_cast<long>(f + 1), static_cast<long>(survey.frames));
    for (OutputFile* output :
         {&frames_file, &contacts_file, &tracks_file})  // a full disk stops the export here, not at its end
      if (output->given()) output->check();
  }
  report.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  if (!survey.failure.empty()) {
    // Everything before the failure kept at PATH.partial, PATH untouched (live_session.cpp does the same).
    std::string kept;
    const auto keep = [&kept](const std::string& path) { kept += (kept.empty() ? " to " : ", ") + path; };
    for (OutputFile& output : outputs)
      if (output.given()) {
        output.finish();
        if (output.kind() == OutputKind::file) keep(output.write_path());
      }
    if (mcap) {
      mcap->close_partial();
      keep(mcap->path() + ".partial");
    }
    throw IoError(survey.failure + "; the " + std::to_string(survey.frames) + " frames before it exported" + kept);
  }
  if (mcap) mcap->close();
  commit_outputs(outputs);  // each finished (a failed write throws here, before any is renamed), then renamed
  return report;
}

}  // namespace emit
