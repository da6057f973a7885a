#include "emit/live/live_loop.hpp"

#include <algorithm>

#include "emit/core/option_check.hpp"
#include "emit/io/contacts_jsonl.hpp"
#include "emit/io/tracks_csv.hpp"

namespace emit {

namespace {

double seconds_between(std::chrono::steady_clock::time_point from, std::chrono::steady_clock::time_point to) {
  return std::chrono::duration<double>(to - from).count();
}

/// The system clock's time [ns since the Unix epoch] at steady-clock time `at` (in the past).
std::uint64_t unix_time_ns_at(std::chrono::steady_clock::time_point at) {
  const auto ago = std::chrono::steady_clock::now() - at;
  return static_cast<std::uint64_t>(
      std::chrono::duration_cast<std::chrono::nanoseconds>(std::chrono::system_clock::now().time_since_epoch() - ago)
          .count());
}

constexpr double rate_smoothing = 0.1;  // weight of each frame's interval in the displayed rate
/// The most contacts tracked a frame (the tracker's limit; a linear method's further regions pass untracked).
constexpr int live_max_contacts = 64;
/// Frames with signal per verdict on the electrodes' health: half a second of pressing at 50
/// frames/s, enough that a press anywhere has moved every electrode's readings.
constexpr int health_window_frames = 25;

}  // namespace

LiveLoop::LiveLoop(FrameSource& source, Pipeline& pipeline, const LiveOptions& options)
    : source_(source),
      options_((options.validate(), options)),  // checked before anything is built for it
      reconstructor_(pipeline.reconstructor(options.frame)),
      tracker_(options.tracking, live_max_contacts, pipeline.model().surface),
      reference_(options.reference),
      no_pressure_(Vector::Zero(pipeline.model().mesh.triangle_count())),
      health_(pipeline.sensor().electrode_count(), pipeline.sensor().adc) {}

bool LiveLoop::command(const std::string& name) {
  if (name != "recapture") return false;
  recapture_requested_ = true;
  return true;
}

LiveStats LiveLoop::run(const std::atomic<bool>& stop) {
  const auto start = std::chrono::steady_clock::now();
  const auto out_of_time = [&] {
    return options_.max_seconds > 0 && seconds_between(start, std::chrono::steady_clock::now()) >= options_.max_seconds;
  };
  const auto measure = [this] {
    stats_.seconds = stats_.frames > 1 ? seconds_between(first_, last_) : 0;
    stats_.frames_per_s = stats_.seconds > 0 ? static_cast<double>(stats_.frames - 1) / stats_.seconds : 0;
    fill_stage_times();
  };
  try {
    // finished() is a source's normal end only: a failed one throws from step() (frame_source.hpp).
    while (!stop && !source_.finished() && !out_of_time() && !stats_.contacts_reader_left &&
           (options_.max_frames == 0 || stats_.frames < options_.max_frames)) {
      step();
    }
  } catch (...) {
    measure();  // stats() tells what the run did before it failed
    throw;
  }
  measure();
  return stats_;
}

const std::vector<Contact>* LiveLoop::step() {
  if (recapture_requested_.exchange(false)) reference_.recapture();
  const auto waiting = std::chrono::steady_clock::now();
  const bool got = source_.next(frame_, options_.poll);
  if (!reference_.capturing()) waited_s_ += seconds_between(waiting, std::chrono::steady_clock::now());
  return got ? handle(frame_) : nullptr;
}

void LiveLoop::fill_stage_times() {
  const double frames = static_cast<double>(std::max<std::uint64_t>(stats_.frames, 1));
  stats_.source_wait_s = waited_s_ / frames;
  stats_.source_make_s = source_.frame_cost_s();
  stats_.reconstruction_s = reconstructing_s_ / frames;
  stats_.output_s = outputting_s_ / frames;
}

const char* LiveStats::bottleneck() const {
  if (std::max(source_wait_s, source_make_s) >= std::max(reconstruction_s, output_s)) return "source";
  return reconstruction_s >= output_s ? "reconstruction" : "output";
}

const std::vector<Contact>* LiveLoop::handle(const SourceFrame& frame) {
  if (handled_ > 0 && frame.sequence > last_sequence_) stats_.frames_missed += frame.sequence - last_sequence_ - 1;
  last_sequence_ = frame.sequence;
  LiveFrame out;
  out.index = handled_++;
  out.sequence = frame.sequence;
  out.volts = &frame.volts;
  out.board_time_s = frame.board_time_s;
  out.host_time_ns = last_host_time_ns_ = unix_time_ns_at(frame.received);
  if (recorder_) {
    const auto recording = std::chrono::steady_clock::now();
    recorder_->record(frame.raw);
    outputting_s_ += seconds_between(recording, std::chrono::steady_clock::now());
  }
  if (reference_.capturing()) {
    tracker_.reset();  // the touches end: a new reference, new contacts
    if (reference_.capture(frame.volts)) reconstructor_.set_reference(reference_.reference());
    ++stats_.capture_frames;
    out.capturing_reference = true;
    out.contacts = &no_contacts_;
    out.pressure_N_per_mm2 = &no_pressure_;
    publish(out);
    return nullptr;
  }
  const auto reconstructing = std::chrono::steady_clock::now();
  const std::vector<Contact>& contacts = tracker_.update(reconstructor_.process(frame.volts), frame.board_time_s);
  out.ended = &tracker_.ended();
  const std::size_t masked = reconstructor_.masked_readings().size();
  out.readings_masked = masked;
  stats_.readings_masked += masked;
  health_.add(frame.volts);
  if (health_.frames_with_signal() >= health_window_frames) {
    dead_electrodes_ = health_.dead();
    swapped_electrodes_ = health_.swapped();
    health_.reset();
  }
  stats_.frames_with_masked += masked > 0 ? 1 : 0;
  if (reference_.follow(frame.volts, !contacts.empty() || masked > 0))  // a glitch is not drift
    reconstructor_.set_reference(reference_.reference());
  const auto outputting = std::chrono::steady_clock::now();
  reconstructing_s_ += seconds_between(reconstructing, outputting);
  if (contacts_out_) write_contacts(out, contacts);
  if (tracks_out_) {
    write_tracks_rows(tracks_out_->stream(), frame.board_time_s, frame.sequence, contacts, out.ended);
    tracks_out_->check();  // a full disk stops the run here
  }
  out.contacts = &contacts;
  out.pressure_N_per_mm2 = &reconstructor_.pressure();
  publish(out);
  if (observer_) observer_(frame, contacts);

  const auto now = std::chrono::steady_clock::now();
  outputting_s_ += seconds_between(outputting, now);
  last_latency_s_ = seconds_between(frame.received, now);
  stats_.latency.add(last_latency_s_);
  if (stats_.frames == 0) first_ = now;
  last_ = now;
  ++stats_.frames;
  return &contacts;
}

void LiveLoop::write_contacts(const LiveFrame& frame, const std::vector<Contact>& contacts) {
  OutputFile& out = *contacts_out_;
  if (out.reader_gone() && !out.reconnect()) {  // a FIFO no one reads now: drop the line
    ++stats_.contacts_dropped;
    return;
  }
  const FitResult* fitted = reconstructor_.fit_result();
  write_contacts_line(out.stream(), static_cast<long>(frame.sequence), contacts,
                      fitted ? 1e3 * fitted->rms_misfit_V : -1,
                      {frame.board_time_s, 1e-9 * static_cast<double>(frame.host_time_ns)}, frame.ended);
  if (out.stream().flush()) return;
  ++stats_.contacts_dropped;
  if (out.clear_interrupted()) return;  // a stop signal while the reader did not read: the loop ends
  if (!out.reader_gone()) out.check();  // throws: a full disk, a device's error
  if (out.kind() != OutputKind::fifo) stats_.contacts_reader_left = true;  // standard output: the run ends
}

void LiveLoop::write_tracks_to(OutputFile* out) {
  tracks_out_ = out;
  if (tracks_out_) write_tracks_header(tracks_out_->stream());
}

void LiveLoop::publish(LiveFrame& frame) {
  const auto now = std::chrono::steady_clock::now();
  if (handled_ > 1) {
    const double interval_s = seconds_between(previous_publish_, now);
    mean_interval_s_ =
        mean_interval_s_ > 0 ? mean_interval_s_ + rate_smoothing * (interval_s - mean_interval_s_) : interval_s;
  }
  previous_publish_ = now;
  frame.frames_per_s = mean_interval_s_ > 0 ? 1 / mean_interval_s_ : 0;
  frame.latency_s = last_latency_s_;
  frame.reference_captures = reference_.captures();
  frame.frames_missed = stats_.frames_missed;
  const FitResult* fitted = reconstructor_.fit_result();
  frame.misfit_mV = fitted && !frame.capturing_reference ? 1e3 * fitted->rms_misfit_V : -1;
  frame.dead_electrodes = &dead_electrodes_;
  frame.swapped_electrodes = &swapped_electrodes_;
  for (FramePublisher* publisher : publishers_) publisher->publish(frame);
}

void LiveOptions::validate() const {
  reference.validate();
  frame.validate();
  tracking.validate();
  option_check::non_negative("LiveOptions", "max_seconds", max_seconds);
  option_check::at_least("LiveOptions", "poll", poll.count(), 1);
}
}  // namespace emit
