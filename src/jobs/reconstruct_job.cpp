#include "emit/jobs/reconstruct_job.hpp"

#include <chrono>
#include <cmath>
#include <filesystem>
#include <numbers>
#include <optional>

#include "emit/acquire/electrode_health.hpp"
#include "emit/core/atomic_file.hpp"
#include "emit/frame/batch.hpp"
#include "emit/io/calibration_json.hpp"
#include "emit/io/contacts_jsonl.hpp"
#include "emit/io/frames_csv.hpp"
#include "emit/pipeline/pipeline.hpp"
#include "emit/render/pressure_map.hpp"
#include "emit/sensor/sensor_json.hpp"

namespace emit {

namespace {

double seconds_since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

void write_image(const Reconstructor& reconstructor, const std::vector<Contact>& contacts, std::size_t frame,
                 Method method, const std::string& dir) {
  std::vector<Circle> outlines;
  outlines.reserve(contacts.size());
  for (const Contact& c : contacts)
    outlines.push_back({Vector2(c.x_mm, c.y_mm), std::sqrt(c.area_mm2 / std::numbers::pi)});
  const std::string title = "frame " + std::to_string(frame) + ": pressure (" + method_name(method) + "), " +
                            std::to_string(contacts.size()) + (contacts.size() == 1 ? " contact" : " contacts");
  write_pressure_map(reconstructor.mesh(), reconstructor.pressure(), outlines, title,
                     dir + "/frame_" + std::to_string(frame) + ".png");
}

}  // namespace

ReconstructReport run_reconstruct_job(const ReconstructJob& job, const Progress& progress) {
  const Sensor sensor = job.sensor_path.empty() ? default_sensor() : load_sensor(job.sensor_path);
  std::optional<Calibration> calibration;
  if (!job.calibration_path.empty()) {
    calibration = load_calibration(job.calibration_path);
    check_calibration_for_method(*calibration, job.method, job.calibration_path);
  }
  if (!job.images_dir.empty()) std::filesystem::create_directories(job.images_dir);
  AtomicFile contacts_file(job.contacts_path);  // fails now, not after the work, if unwritable

  // The frames before anything is built or written: a bad value stops the run with nothing lost.
  const int N = electrode_count_of(sensor);
  const Frame reference = average_frames(read_frames_csv(job.reference_path, N));
  const std::vector<Frame> frames = read_frames_csv(job.frames_path, N);
  ReconstructReport report;
  PipelineOptions options{job.method, job.lambda2, job.cache_dir, {}};
  for (const DeadElectrode& d : find_dead_electrodes(frames, sensor.adc)) {
    progress.warn("electrode " + std::to_string(d.electrode) + " " + d.reason + ": leaving out its " +
                  std::to_string(2 * (N - 1)) + " measurements");
    options.excluded.push_back(d.electrode);
  }
  report.dead_electrodes = options.excluded;
  check_no_stuck_rows(frames, sensor.adc, options.excluded, job.frames_path);

  const auto start = std::chrono::steady_clock::now();
  Pipeline pipeline(sensor, options, calibration, progress.stage, job.calibration_path);
  const ReconstructionModel& model = pipeline.model();
  report.model_seconds = seconds_since(start);
  report.triangles = static_cast<long>(model.mesh.triangle_count());
  report.measurements = model.measurements.size();
  report.operator_from_cache = model.loaded_from_cache;
  report.lambda2 = pipeline.operator_options().lambda2;
  report.calibrated = pipeline.calibrated();
  report.frames = frames.size();

  FrameOptions frame_options;
  frame_options.threshold_fraction = job.threshold_fraction;
  frame_options.min_contact_area_mm2 = job.min_contact_area_mm2;
  const auto online_start = std::chrono::steady_clock::now();
  if (is_linear(job.method) && job.images_dir.empty()) {
    // The linear methods' frames are independent: a batch, split across threads.
    const auto contacts =
        reconstruct_batch(model, pipeline.linear_calibration(), frame_options, reference, frames, job.threads);
    for (std::size_t f = 0; f < frames.size(); ++f)
      write_contacts_line(contacts_file.stream(), static_cast<long>(f), contacts[f], -1);
  } else {
    Reconstructor reconstructor = pipeline.reconstructor(frame_options);
    reconstructor.set_reference(reference);
    for (std::size_t f = 0; f < frames.size(); ++f) {
      const auto& contacts = reconstructor.process(frames[f]);
      const FitResult* fitted = reconstructor.fit_result();
      write_contacts_line(contacts_file.stream(), static_cast<long>(f), contacts,
                          fitted ? 1e3 * fitted->rms_misfit_V : -1);
      if (!job.images_dir.empty()) write_image(reconstructor, contacts, f, job.method, job.images_dir);
      progress.step("reconstructing frame", static_cast<long>(f + 1), static_cast<long>(frames.size()));
    }
  }
  contacts_file.commit();
  report.frames_per_s = static_cast<double>(frames.size()) / std::max(seconds_since(online_start), 1e-9);
  return report;
}

}  // namespace emit
