// emit reconstruct: frames → contacts (JSON Lines) and, on request, a pressure map per frame.
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <optional>

#include "commands.hpp"
#include "emit/errors.hpp"
#include "emit/io/atomic_file.hpp"
#include "emit/io/calibration_json.hpp"
#include "emit/io/contacts_jsonl.hpp"
#include "emit/io/frames_csv.hpp"
#include "emit/mesh/element_to_node.hpp"
#include "emit/reconstruct/batch.hpp"
#include "emit/reconstruct/electrode_health.hpp"
#include "emit/reconstruct/operator_cache.hpp"
#include "emit/reconstruct/reconstruction_setup.hpp"
#include "emit/reconstruct/reconstructor.hpp"
#include "emit/render/field_image.hpp"
#include "emit/threads.hpp"

namespace emit::cli {

namespace {

struct ReconstructArgs {
  std::string sensor_path, reference_path, frames_path, contacts_path, calibration_path, images_dir;
  std::string method = "fit", cache_dir;
  double lambda2 = 0, threshold = 0.5, min_area_mm2 = 0;
  bool no_cache = false;
};

void write_pressure_image(const Reconstructor& reconstructor, const std::vector<Contact>& contacts, long frame,
                          const std::string& method, const std::string& path) {
  std::vector<Circle> outlines;
  for (const Contact& c : contacts) outlines.push_back({Vector2(c.x_mm, c.y_mm), std::sqrt(c.area_mm2 / M_PI)});
  FieldImageOptions image;
  image.title = "frame " + std::to_string(frame) + ": pressure (" + method + "), " + std::to_string(contacts.size()) +
                (contacts.size() == 1 ? " contact" : " contacts");
  image.unit = "N/mm2";
  image.min_value = 0;
  write_png(render_field(reconstructor.mesh(), element_to_node(reconstructor.mesh(), reconstructor.pressure()),
                         outlines, image),
            path);
}

void run_reconstruct(const ReconstructArgs& args) {
  const Sensor sensor = sensor_from_option(args.sensor_path);
  const bool fit = args.method == "fit";
  const PressureCalibration calibration =
      args.calibration_path.empty() ? PressureCalibration::uncalibrated(sensor) : load_calibration(args.calibration_path);
  check_calibration_for_method(calibration, args.method, args.calibration_path);
  if (!args.images_dir.empty()) std::filesystem::create_directories(args.images_dir);
  AtomicFile contacts_file(args.contacts_path);  // fails now, not after the work, if unwritable

  // Read the frames before anything is built or written: a bad value stops the run with nothing lost.
  const int N = electrode_count_of(sensor);
  const Frame reference = average_frames(read_frames_csv(args.reference_path, N));
  const std::vector<Frame> frames = read_frames_csv(args.frames_path, N);
  SetupOptions setup_options;
  setup_options.method = args.method;
  setup_options.lambda2 = args.lambda2;
  setup_options.cache_dir = args.no_cache ? "" : (args.cache_dir.empty() ? default_cache_dir() : args.cache_dir);
  for (const DeadElectrode& d : find_dead_electrodes(frames, sensor.adc)) {
    std::fprintf(stderr, "emit: warning: electrode %d %s: leaving out its %d measurements\n", d.electrode,
                 d.reason.c_str(), 2 * (N - 1));
    setup_options.excluded.push_back(d.electrode);
  }
  check_no_stuck_rows(frames, sensor.adc, setup_options.excluded, args.frames_path);

  const auto start = std::chrono::steady_clock::now();
  const auto say = [](const std::string& stage) { std::fprintf(stderr, "%s ...\n", stage.c_str()); };
  ReconstructionSetup setup(sensor, calibration, setup_options, say);
  const ReconstructionModel& model = setup.model();
  std::fprintf(stderr, "model ready in %.2f s (%lld triangles, %d measurements%s)\n",
               std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(),
               static_cast<long long>(model.mesh.triangle_count()), model.measurements.size(),
               model.loaded_from_cache ? ", operator from the cache" : "");

  FrameOptions frame_options;
  frame_options.threshold_fraction = args.threshold;
  frame_options.min_contact_area_mm2 = args.min_area_mm2;
  const auto online_start = std::chrono::steady_clock::now();
  if (!fit && args.images_dir.empty()) {
    // The linear methods' frames are independent: a batch, split across --threads.
    const auto contacts = reconstruct_batch(model, calibration, frame_options, reference, frames, thread_count());
    for (std::size_t f = 0; f < frames.size(); ++f) write_contacts_line(contacts_file.stream(), static_cast<long>(f), contacts[f], -1);
  } else {
    Reconstructor reconstructor = setup.reconstructor(frame_options);
    reconstructor.set_reference(reference);
    Progress progress("reconstructing frame", static_cast<int>(frames.size()));
    for (std::size_t f = 0; f < frames.size(); ++f) {
      const auto& contacts = reconstructor.process(frames[f]);
      const FitResult* fitted = reconstructor.fit_result();
      write_contacts_line(contacts_file.stream(), static_cast<long>(f), contacts, fitted ? 1e3 * fitted->rms_misfit_V : -1);
      if (!args.images_dir.empty())
        write_pressure_image(reconstructor, contacts, static_cast<long>(f), args.method,
                             args.images_dir + "/frame_" + std::to_string(f) + ".png");
      if (frames.size() >= 20) progress.step(static_cast<int>(f + 1));
    }
    if (frames.size() >= 20) progress.finish();
  }
  contacts_file.commit();
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - online_start).count();
  char lambda[48] = "";
  if (!fit) std::snprintf(lambda, sizeof lambda, " (lambda2 = %g)", setup.operator_options().lambda2);
  std::printf("reconstructed %zu frames (%.0f frames/s%s) with the %s method%s; contacts in %s\n", frames.size(),
              frames.size() / std::max(seconds, 1e-9), args.images_dir.empty() ? "" : ", with images",
              args.method.c_str(), lambda, args.contacts_path.c_str());
  if (!calibration.calibrated) std::printf("note: pressures are uncalibrated; run 'emit calibrate' for N/mm2 you can trust\n");
}

}  // namespace

void add_reconstruct_command(CLI::App& app) {
  auto a = std::make_shared<ReconstructArgs>();
  CLI::App* cmd = app.add_subcommand("reconstruct", "Reconstruct pressure images and contacts from frames");
  cmd->footer("Example:\n  emit reconstruct --reference ref.csv --frames frames.csv --contacts contacts.jsonl --images out/");
  cmd->add_option("--sensor", a->sensor_path, "Sensor description (JSON); default: the built-in 60 mm sensor")
      ->check(CLI::ExistingFile);
  cmd->add_option("--reference", a->reference_path, "No-contact frames (CSV; several rows are averaged)")
      ->required()
      ->check(CLI::ExistingFile);
  cmd->add_option("--frames", a->frames_path, "Frames to reconstruct (CSV)")->required()->check(CLI::ExistingFile);
  cmd->add_option("--contacts", a->contacts_path, "Contacts out (JSON Lines, one object per frame)")->required();
  cmd->add_option("--calibration", a->calibration_path, "Pressure calibration (JSON from 'emit calibrate')")
      ->check(CLI::ExistingFile);
  cmd->add_option("--method", a->method, "fit (model-based contact fitting), paper (Tikhonov, Q = I), noser, or laplacian")
      ->check(CLI::IsMember({"fit", "paper", "noser", "laplacian"}))
      ->capture_default_str();
  cmd->add_option("--lambda2", a->lambda2, "Regularisation lambda^2 (default: the method's)")->check(CLI::PositiveNumber);
  cmd->add_option("--threshold", a->threshold, "Threshold as a fraction of the image's maximum")->capture_default_str();
  cmd->add_option("--min-area-mm2", a->min_area_mm2, "Drop contacts smaller than this")->check(CLI::NonNegativeNumber);
  cmd->add_option("--images", a->images_dir, "Write a pressure map per frame (PNG) into this folder");
  cmd->add_option("--cache", a->cache_dir, "Operator cache folder (default: $EMIT_CACHE_DIR or ~/.cache/emit)");
  cmd->add_flag("--no-cache", a->no_cache, "Neither read nor write the operator cache");
  cmd->callback([a] { run_reconstruct(*a); });
}

}  // namespace emit::cli
