#include "emit/jobs/live_session.hpp"
#include "emit/mesh/sheet_file.hpp"

#include <array>
#include <filesystem>
#include <optional>
#include <vector>

#include "emit/acquire/recorder.hpp"
#include "emit/core/option_check.hpp"
#include "emit/core/output_paths.hpp"
#include "emit/io/calibration_json.hpp"
#include "emit/live/dds_publisher.hpp"
#include "emit/live/live_server.hpp"
#include "emit/live/mcap_publisher.hpp"
#include "emit/live/open_source.hpp"
#include "emit/pipeline/pipeline.hpp"
#include "emit/sensor/sensor_json.hpp"

namespace emit {

namespace {

/// HOST:PORT whose host is a wildcard address (every interface).
bool is_every_interface(const std::string& serve) {
  const std::string host = serve.substr(0, serve.rfind(':'));
  return host == "0.0.0.0" || host == "::" || host == "[::]";
}

}  // namespace

struct LiveSession::Impl {
  Sensor sensor;
  std::unique_ptr<FrameSource> source;
  std::optional<Pipeline> pipeline;
  std::optional<LiveLoop> loop;
  std::optional<LiveServer> server;
  std::optional<Recorder> recorder;
  std::optional<McapPublisher> mcap;
  std::optional<DdsPublisher> dds;
  std::array<OutputFile, 4> outputs;  ///< --contacts, --tracks, --record, --mcap (the last two moved to their writers)
  std::vector<std::string> partial_paths;  ///< the PATH.partial each regular file grows as
  std::vector<std::string> kept;           ///< those a failed run left (LiveSession::kept_partial)

  /// A failed run: every output flushed and closed as it is, none renamed (file's comment in the
  /// header). Their own errors are dropped: the failure that ended the run is the one to report.
  void keep_what_was_written() {
    const auto quietly = [](auto&& close) {
      try {
        close();
      } catch (const std::exception&) {  // e.g. the writer that failed, failing again
      }
    };
    if (recorder) quietly([&] { recorder->close_partial(); });
    if (mcap) quietly([&] { mcap->close_partial(); });
    for (OutputFile* output : {&outputs[0], &outputs[1]})  // the contacts and the tracks
      if (output->given()) quietly([&] { output->finish(); });
    for (const std::string& path : partial_paths) {
      std::error_code error;
      if (std::filesystem::file_size(path, error) > 0 && !error) kept.push_back(path);
    }
  }
};

LiveSession::LiveSession(const LiveJob& job, const Progress& progress) : impl_(std::make_unique<Impl>()) {
  Impl& s = *impl_;
  const std::string source_file = job.source.rfind("file:", 0) == 0 ? job.source.substr(5) : "";
  if (!job.dds_prefix.empty()) DdsOptions{job.dds_prefix, job.dds_domain, job.frame_id}.validate();
  option_check::non_negative("LiveJob", "pressure_range_N_per_mm2", job.pressure_range_N_per_mm2);
  check_ros2_frame_id(job.frame_id);
  LiveOptions live_options;
  live_options.frame.contact_radius_mm = job.contact_radius_mm;
  live_options.tracking = job.tracking;
  check_frame_options(job.method, live_options.frame);
  // Every output opened before any input is read: one that cannot be opened touches none. Each
  // file grows as PATH.partial while the run lasts and is renamed to PATH at its end.
  s.outputs =
      open_outputs({{"--sensor", job.sensor_path}, {"--calibration", job.calibration_path}, {"--source", source_file}},
                   {OutputRequest{{"--contacts", job.contacts_path}, {.partial = true, .standard_output = true}},
                    OutputRequest{{"--tracks", job.tracks_path}, {.partial = true}},
                    OutputRequest{{"--record", job.record_path}, {.partial = true}},
                    OutputRequest{{"--mcap", job.mcap_path}, {.partial = true}}});
  auto& [contacts, tracks, record, mcap] = s.outputs;
  for (const OutputFile& output : s.outputs)
    if (output.given() && output.kind() == OutputKind::file) s.partial_paths.push_back(output.write_path());
  if (is_every_interface(job.serve))
    progress.warn("--serve " + job.serve + ": the viewer is open to every computer that can reach this one; " +
                  "use 127.0.0.1:PORT to keep it on this computer");
  s.sensor = load_sheet_sensor(job.sensor_path);
  require_emit_protocol(s.sensor, job.sensor_path);
  std::optional<Calibration> calibration;
  if (!job.calibration_path.empty()) {
    calibration = load_calibration(job.calibration_path);
    check_calibration_for_method(*calibration, job.method, job.calibration_path);
  }
  SourceOptions source_options;
  source_options.frames_per_s = job.frames_per_s;
  source_options.loop = job.loop;
  source_options.reconnect_s = job.reconnect_s;
  s.source = open_source(job.source, s.sensor, source_options);
  s.pipeline.emplace(s.sensor, PipelineOptions{job.method, 0, job.cache_dir, {}}, calibration, progress.stage,
                     job.calibration_path);
  live_options.max_frames = job.frames;
  live_options.max_seconds = job.seconds;
  s.loop.emplace(*s.source, *s.pipeline, live_options);
  if (!job.serve.empty()) {
    s.server.emplace(job.serve, s.pipeline->model().mesh,
                     ViewerSheet{s.sensor.name, s.pipeline->calibrated(), job.pressure_range_N_per_mm2,
                                 s.sensor.adc.vref_V},
                     [&loop = *s.loop](const std::string& command) { loop.command(command); });
    s.loop->add_publisher(&*s.server);
  }
  if (contacts.given()) s.loop->write_contacts_to(&contacts);
  if (tracks.given()) s.loop->write_tracks_to(&tracks);
  if (mcap.given())
    s.loop->add_publisher(&s.mcap.emplace(std::move(mcap), s.sensor.name, s.pipeline->model().mesh, job.frame_id));
  if (!job.dds_prefix.empty())
    s.loop->add_publisher(&s.dds.emplace(DdsOptions{job.dds_prefix, job.dds_domain, job.frame_id}, s.sensor.name,
                                         s.pipeline->model().mesh));
  // Last: a Recorder's destructor renames its file into place, so nothing may fail after it.
  if (record.given()) s.loop->record_to(&s.recorder.emplace(std::move(record), s.sensor));
}

LiveSession::~LiveSession() = default;

std::string LiveSession::source_description() const { return impl_->source->description(); }
std::string LiveSession::viewer_url() const { return impl_->server ? impl_->server->url() : ""; }
bool LiveSession::calibrated() const { return impl_->pipeline->calibrated(); }
std::uint64_t LiveSession::recorded_frames() const { return impl_->recorder ? impl_->recorder->frames() : 0; }

const LiveStats& LiveSession::stats() const { return impl_->loop->stats(); }
const std::vector<std::string>& LiveSession::kept_partial() const { return impl_->kept; }

LiveStats LiveSession::run(const std::atomic<bool>& stop) {
  Impl& s = *impl_;
  LiveStats stats;
  try {
    stats = s.loop->run(stop);
  } catch (...) {
    s.keep_what_was_written();
    throw;
  }
  if (s.recorder) s.recorder->close();
  if (s.mcap) s.mcap->close();
  // A reader that went away has had every line it could take: there is nothing left to flush.
  if (OutputFile& contacts = s.outputs[0]; contacts.given() && !contacts.reader_gone()) contacts.commit();
  if (OutputFile& tracks = s.outputs[1]; tracks.given()) tracks.commit();
  return stats;
}

}  // namespace emit
