#include "emit/jobs/reconstruct_job.hpp"
#include "emit/mesh/sheet_file.hpp"

#include <chrono>
#include <cmath>
#include <optional>

#include "emit/acquire/electrode_health.hpp"
#include "emit/core/errors.hpp"
#include "emit/core/option_check.hpp"
#include "emit/core/output_paths.hpp"
#include "emit/frame/batch.hpp"
#include "emit/io/contacts_jsonl.hpp"
#include "emit/io/frames_csv.hpp"
#include "emit/io/ros2_messages.hpp"
#include "emit/io/tactile_mcap.hpp"
#include "emit/io/tracks_csv.hpp"
#include "emit/pipeline/pipeline.hpp"
#include "emit/render/pressure_map.hpp"
#include "emit/sensor/adc.hpp"
#include "emit/sensor/sensor_json.hpp"
#include "reconstruct_inputs.hpp"
#include "reference_frames.hpp"

namespace emit {

namespace {

double seconds_since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

void write_image(const Reconstructor& reconstructor, const std::vector<Contact>& contacts, std::size_t frame,
                 Method method, bool calibrated, const std::string& dir, const PressureMapOptions& options) {
  std::vector<Circle> outlines;
  outlines.reserve(contacts.size());
  for (const Contact& c : contacts) {
    outlines.push_back(contact_outline(c, reconstructor.surface()));
    outlines.back().label = contact_label(c);
  }
  // Uncalibrated pressures are the sensor file's nominal contact law's: the picture says so.
  const std::string title = "frame " + std::to_string(frame) + ": pressure (" + method_name(method) +
                            (calibrated ? "" : ", uncalibrated") + "), " + std::to_string(contacts.size()) +
                            (contacts.size() == 1 ? " contact" : " contacts");
  write_pressure_map(reconstructor.mesh(), reconstructor.pressure(), outlines, title,
                     dir + "/" + frame_image_name(frame), options);
}

}  // namespace

namespace {

/// What a first pass over the frames file finds: how many frames, the dead electrodes, and the
/// readings the reconstructor will mask (not finite, or clipped: frame/masked_readings.hpp).
struct FramesSurvey {
  long frames = 0;
  std::vector<DeadElectrode> dead;
  std::vector<SwappedElectrodes> swapped;
  long readings_masked = 0, frames_with_masked = 0;
};

/// Reads every frame once (checking every value) without keeping them: a bad value stops the run
/// before anything is built or written, in constant memory whatever the file's length.
FramesSurvey survey_frames(const std::string& path, const Sensor& sensor, int N) {
  FramesCsvReader reader(path, N, true);
  ElectrodeHealthTally health(N, sensor.adc);
  FramesSurvey survey;
  const double clipped = clipped_at_V(sensor.adc);
  for (Frame frame; reader.next(frame); ++survey.frames) {
    check_readings_in_range(frame, sensor.adc, reader.where());
    health.add(frame);
    long masked = 0;
    for (Index l = 0; l < N; ++l)
      for (Index m = 0; m < N; ++m) masked += l != m && !(std::isfinite(frame(l, m)) && frame(l, m) < clipped) ? 1 : 0;
    survey.readings_masked += masked;
    survey.frames_with_masked += masked > 0 ? 1 : 0;
  }
  if (survey.frames == 0) throw InvalidInput(path + ": no frames (an empty file?)");
  survey.dead = health.dead();
  survey.swapped = health.swapped();
  return survey;
}

/// Frames are reconstructed in chunks of this many: the linear methods' batch splits a chunk
/// across threads, and memory stays bounded (256 × 16² doubles = 0.5 MB).
constexpr std::size_t chunk_frames = 256;

}  // namespace

ReconstructReport run_reconstruct_job(const ReconstructJob& job, const Progress& progress) {
  // Every output opened before any input is read: one that cannot be opened touches none.
  auto outputs = open_outputs({{"--sensor", job.sensor_path},
                               {"--reference", job.reference_path},
                               {"--frames", job.frames_path},
                               {"--calibration", job.calibration_path}},
                              {OutputRequest{{"--contacts", job.contacts_path}, {.standard_output = true}},
                               OutputRequest{{"--tracks", job.tracks_path}},
                               OutputRequest{{"--mcap", job.mcap_path}, {.partial = true}}});
  OutputFile &contacts_file = outputs[0], &tracks_file = outputs[1], &mcap_file = outputs[2];
  job.tracking.validate();  // checked before anything is read
  job.images.validate();
  option_check::positive("ReconstructJob", "frames_per_s", job.frames_per_s);
  FrameOptions declared;
  declared.contact_radius_mm = job.contact_radius_mm;
  check_frame_options(job.method, declared);
  const Sensor sensor = load_sheet_sensor(job.sensor_path);
  require_emit_protocol(sensor, job.sensor_path);
  const std::optional<Calibration> calibration =
      detail::load_job_calibration(job.calibration_path, job.method, progress);
  prepare_output_folder({"--images", job.images_dir});

  // The frames before anything is built or written: a bad value stops the run with nothing lost.
  const int N = electrode_count_of(sensor);
  const Reference reference = detail::read_reference(job.reference_path, sensor, N, progress);
  const FramesSurvey survey = survey_frames(job.frames_path, sensor, N);
  ReconstructReport report;
  PipelineOptions options{job.method, job.lambda2, job.cache_dir, {}};
  options.excluded = detail::leave_out_dead(survey.dead, N, progress);
  report.dead_electrodes = options.excluded;
  for (const SwappedElectrodes& w : survey.swapped)
    progress.warn("electrodes " + std::to_string(w.a) + " and " + std::to_string(w.b) + " look swapped: " + w.reason +
                  " (check the wiring)");

  const auto start = std::chrono::steady_clock::now();
  Pipeline pipeline(sensor, options, calibration, progress.stage, job.calibration_path);
  const ReconstructionModel& model = pipeline.model();
  report.model_seconds = seconds_since(start);
  report.triangles = static_cast<long>(model.mesh.triangle_count());
  report.measurements = model.measurements.size();
  report.operator_from_cache = model.loaded_from_cache;
  report.lambda2 = pipeline.operator_options().lambda2;
  report.calibrated = pipeline.calibrated();
  report.frames = static_cast<std::size_t>(survey.frames);
  report.readings_masked = survey.readings_masked;
  report.frames_with_masked = survey.frames_with_masked;

  FrameOptions frame_options;
  frame_options.threshold_fraction = job.threshold_fraction;
  frame_options.min_contact_area_mm2 = job.min_contact_area_mm2;
  frame_options.contact_radius_mm = job.contact_radius_mm;
  // Frames independent: split across threads (unless each frame's image is wanted).
  const bool batch = is_linear(job.method) && job.images_dir.empty() && job.mcap_path.empty();
  std::optional<Reconstructor> reconstructor;
  if (!batch) {
    reconstructor.emplace(pipeline.reconstructor(frame_options));
    reconstructor->set_reference(reference);
  }
  // A file of frames has no times: frame f is at f / frames_per_s (the board's 50 frames/s unless
  // told), for the tracker and, from now, for the recording.
  const std::uint64_t start_ns = unix_time_ns();
  const double frame_s = 1 / job.frames_per_s;
  const auto frame_ns = static_cast<std::uint64_t>(std::llround(1e9 * frame_s));
  ContactTracker tracker(job.tracking, 64, model.surface);
  if (tracks_file.given()) write_tracks_header(tracks_file.stream());
  std::optional<TactileMcap> mcap;
  if (mcap_file.given()) mcap.emplace(std::move(mcap_file), sensor.name, model.mesh, start_ns);
  const auto online_start = std::chrono::steady_clock::now();
  FramesCsvReader reader(job.frames_path, N, true);
  std::vector<Frame> chunk;
  chunk.reserve(chunk_frames);
  for (std::size_t first = 0; first < report.frames; first += chunk_frames) {
    chunk.clear();
    for (Frame frame; chunk.size() < chunk_frames && reader.next(frame);) chunk.push_back(frame);
    const std::size_t count = chunk.size();
    // Each frame's contacts tracked, then written: its line (with its board time and the touches
    // that ended) and its tracks' rows.
    const auto track_and_write = [&](std::size_t index, const std::vector<Contact>& found, double misfit_mV) {
      const double time_s = static_cast<double>(index) * frame_s;
      const std::vector<Contact>& contacts = tracker.update(found, time_s);
      write_contacts_line(contacts_file.stream(), static_cast<long>(index), contacts, misfit_mV, FrameTimes{time_s},
                          &tracker.ended());
      if (tracks_file.given()) write_tracks_rows(tracks_file.stream(), time_s, index, contacts, &tracker.ended());
      return &contacts;
    };
    if (batch) {
      const auto contacts = pipeline.reconstruct_batch(frame_options, reference, chunk, job.threads);
      for (std::size_t f = 0; f < count; ++f) track_and_write(first + f, contacts[f], -1);
    } else {
      for (std::size_t f = 0; f < count; ++f) {
        const auto& found = reconstructor->process(chunk[f]);
        const FitResult* fitted = reconstructor->fit_result();
        const std::vector<Contact>& contacts =
            *track_and_write(first + f, found, fitted != nullptr ? 1e3 * fitted->rms_misfit_V : -1);
        if (!job.images_dir.empty())
          write_image(*reconstructor, contacts, first + f, job.method, report.calibrated, job.images_dir, job.images);
        if (mcap)
          mcap->write(first + f, start_ns + (first + f) * frame_ns, frame_view(chunk[f]), contacts,
                      reconstructor->pressure(), static_cast<double>(first + f) * frame_s, &tracker.ended());
        progress.step("reconstructing frame", static_cast<long>(first + f + 1), survey.frames);
      }
    }
    if (batch) progress.step("reconstructing frame", static_cast<long>(first + count), survey.frames);
    contacts_file.check();  // a full disk or a reader gone stops the run here, not at its end
    if (tracks_file.given()) tracks_file.check();
  }
  contacts_file.finish();
  if (tracks_file.given()) tracks_file.finish();
  if (mcap) mcap->close();
  contacts_file.commit();
  if (tracks_file.given()) tracks_file.commit();
  report.frames_per_s = static_cast<double>(report.frames) / std::max(seconds_since(online_start), 1e-9);
  return report;
}

}  // namespace emit
