#pragma once
/// \file live_loop.hpp
/// The live path: source → reference (frame/reference.hpp) → Reconstructor → ContactTracker (ids,
/// phases, velocities: frame/contact_tracker.hpp) → contacts (JSON Lines) and publishers (the
/// viewer's server). One thread runs it; commands (re-capture the reference) may
/// come from any thread and are applied between frames. It measures frames/s and end-to-end
/// latency: from SourceFrame::received to the frame's contacts written and published.
#include <atomic>
#include <chrono>
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "emit/acquire/electrode_health.hpp"
#include "emit/acquire/frame_source.hpp"
#include "emit/acquire/recorder.hpp"
#include "emit/core/output_file.hpp"
#include "emit/frame/contact_tracker.hpp"
#include "emit/frame/reference.hpp"
#include "emit/live/latency_stats.hpp"
#include "emit/pipeline/pipeline.hpp"

namespace emit {

/// One frame as the loop publishes it; the pointers are valid during publish() only.
struct LiveFrame {
  std::uint64_t index = 0;           ///< frames the loop has handled before this one (capture included)
  std::uint64_t sequence = 0;        ///< the source's number
  bool capturing_reference = false;  ///< no reference yet, or a re-capture under way: no contacts
  std::uint64_t reference_captures = 0;
  const Frame* volts = nullptr;    ///< the frame as the source gave it
  double board_time_s = 0;         ///< when the board took it, on the board's clock (SourceFrame)
  std::uint64_t host_time_ns = 0;  ///< when it reached the host, ns since the Unix epoch (system clock)
  const std::vector<Contact>* contacts = nullptr;
  /// The touches that ended with this frame, their last state (frame/contact_tracker.hpp); null: none.
  const std::vector<Contact>* ended = nullptr;
  const Vector* pressure_N_per_mm2 = nullptr;  ///< per triangle of the reconstruction mesh
  double frames_per_s = 0;                     ///< recent rate (over about the last second)
  double latency_s = 0;                        ///< the previous frame's end-to-end latency
  std::uint64_t frames_missed = 0;             ///< so far in the run (LiveStats::frames_missed)
  double misfit_mV = -1;                       ///< the contact fit's RMS misfit; < 0: no fit (a linear method)
  std::size_t readings_masked = 0;             ///< in this frame (LiveStats::readings_masked)
  /// Electrodes dead in the last window of frames with signal (LiveLoop's health window); never null.
  const std::vector<DeadElectrode>* dead_electrodes = nullptr;
  /// Pairs wired in each other's places, found over the same window; never null.
  const std::vector<SwappedElectrodes>* swapped_electrodes = nullptr;
};

/// Receives every frame the loop handles (the viewer's server). Called on the loop's thread; it
/// must not block on clients.
class FramePublisher {
 public:
  virtual ~FramePublisher() = default;
  virtual void publish(const LiveFrame& frame) = 0;
};

struct LiveOptions {
  ReferenceOptions reference;  ///< its capture and drift (frame/reference.hpp)
  FrameOptions frame;
  /// Touches over time: each frame's contacts tracked at the frame's board time (SourceFrame::board_time_s).
  TrackerOptions tracking;
  /// Stop after this many reconstructed frames (the reference capture's frames do not count); 0: run until stopped.
  std::uint64_t max_frames = 0;
  /// Stop after this many seconds of running; 0: no limit.
  double max_seconds = 0;
  /// How long next() waits before the loop looks at commands and the stop flag again.
  std::chrono::milliseconds poll{50};
  void validate() const;  ///< \throw InvalidInput naming the option (core/option_check.hpp)
};

struct LiveStats {
  std::uint64_t frames = 0;  ///< reconstructed (and written, and published)
  std::uint64_t capture_frames = 0;
  /// Frames the source numbered but never handed out: the sum of the gaps between consecutive
  /// sequence numbers (a number at or behind the last one, a source that started again, is no gap).
  std::uint64_t frames_missed = 0;
  /// Readings masked (not finite, or clipped at the ADC's top code: frame/masked_readings.hpp), and
  /// the reconstructed frames that had any. Such a frame does not move the reference's drift.
  std::uint64_t readings_masked = 0, frames_with_masked = 0;
  double seconds = 0;  ///< from the first reconstructed frame to the last
  double frames_per_s = 0;
  LatencyStats latency;  ///< end to end, per reconstructed frame
  /// Contacts lines not written because no one read them: a FIFO's reader had gone and no new
  /// one had come yet, or the line whose write found standard output's reader gone.
  std::uint64_t contacts_dropped = 0;
  /// The run ended because the reader of the contacts went away (standard output or another
  /// descriptor's pipe closed, as `| head` does); a FIFO's reader may come back instead.
  bool contacts_reader_left = false;
  /// Time per reconstructed frame by stage [s], means over the run: the loop waiting for the
  /// source; the source making a frame on its own thread (FrameSource::frame_cost_s: the twin's
  /// solve; 0 for a board or a recording); the reconstruction (with the reference's tracking); the
  /// output (the recording, the contacts written, the publishers: viewer, MCAP, DDS).
  double source_wait_s = 0, source_make_s = 0, reconstruction_s = 0, output_s = 0;
  /// The stage that sets the rate: "source" when the loop waits for frames longer than it works
  /// on one (or the source takes longer to make one than the loop), else the loop's slower stage,
  /// "reconstruction" or "output".
  const char* bottleneck() const;
};

class LiveLoop {
 public:
  /// `source` and `pipeline` must outlive the loop. \throw InvalidInput for a bad option.
  LiveLoop(FrameSource& source, Pipeline& pipeline, const LiveOptions& options = {});

  /// Contacts as JSON Lines (contacts_jsonl.hpp), "frame" = the source's sequence number, one line
  /// per reconstructed frame, flushed each frame. Null: none. When its reader goes away (EPIPE):
  /// a FIFO's lines are dropped until a new reader opens it, whole lines from the next frame on;
  /// standard output (a pipe that cannot be reopened) ends the run (LiveStats::contacts_reader_left).
  /// Any other failed write throws IoError naming the output. Must outlive run().
  void write_contacts_to(OutputFile* out) { contacts_out_ = out; }
  /// Tracked contacts as CSV rows (io/tracks_csv.hpp), time = the board's; its header first.
  /// Null: none. A failed write throws IoError naming the output. Must outlive run().
  void write_tracks_to(OutputFile* out);
  /// Every frame the source gives (the reference's capture included) is recorded here, as the board sent
  /// it (SourceFrame::raw). Null: none.
  void record_to(Recorder* recorder) { recorder_ = recorder; }
  /// Must outlive run(). Several may be added.
  void add_publisher(FramePublisher* publisher) { publishers_.push_back(publisher); }
  /// Told each reconstructed frame with its contacts (for tests and tools).
  void on_frame(std::function<void(const SourceFrame&, const std::vector<Contact>&)> observer) {
    observer_ = std::move(observer);
  }

  /// A command from any thread, applied before the next frame: "recapture" (the reference).
  /// \return false for an unknown command (ignored).
  bool command(const std::string& name);

  /// Runs until `stop` is set, max_frames are reconstructed, the source has finished (a
  /// recording's end: a normal end) or the contacts' reader went away. Returns what it measured.
  /// \throw IoError (or what else was thrown) when the source, a publisher or the contacts' writer
  ///   fails: a failure never ends the run as an end would. stats() then holds what was measured
  ///   up to it; what was written stays written (the caller closes the outputs).
  LiveStats run(const std::atomic<bool>& stop);

  /// One turn of run()'s loop, for a caller that pulls frames (the Python iterator): applies a
  /// pending command, waits up to the poll for the source's next frame and handles it.
  /// \return the frame's contacts when it was reconstructed (valid until the next step); null
  /// when no frame came or it went to the reference's capture. \throw IoError as run() does.
  const std::vector<Contact>* step();
  /// The last frame the source gave, and the reconstructor (its pressure and image are the last
  /// reconstructed frame's).
  const SourceFrame& last_frame() const { return frame_; }
  /// When the last frame handled reached the host [ns since the Unix epoch, the system clock].
  std::uint64_t last_host_time_ns() const { return last_host_time_ns_; }
  const Reconstructor& reconstructor() const { return reconstructor_; }
  /// The tracker: its ended() are the touches that ended at the last reconstructed frame (their ups).
  /// Every touch ends when the reference is captured again (reported at the next reconstructed frame).
  const ContactTracker& tracker() const { return tracker_; }
  const LiveStats& stats() const { return stats_; }

 private:
  /// \return the contacts of a reconstructed frame; null for a capture frame.
  const std::vector<Contact>* handle(const SourceFrame& frame);
  void publish(LiveFrame& frame);
  void fill_stage_times();  ///< LiveStats' time per frame by stage, from the totals
  void write_contacts(const LiveFrame& frame, const std::vector<Contact>& contacts);

  FrameSource& source_;
  LiveOptions options_;
  Reconstructor reconstructor_;
  ContactTracker tracker_;
  ReferenceTracker reference_;
  OutputFile* contacts_out_ = nullptr;
  OutputFile* tracks_out_ = nullptr;
  Recorder* recorder_ = nullptr;
  std::vector<FramePublisher*> publishers_;
  std::function<void(const SourceFrame&, const std::vector<Contact>&)> observer_;
  std::atomic<bool> recapture_requested_{false};
  SourceFrame frame_;
  Vector no_pressure_;
  const std::vector<Contact> no_contacts_;
  /// The electrodes' health over windows of frames with signal: each full window's verdict is
  /// published until the next window is full.
  ElectrodeHealthTally health_;
  std::vector<DeadElectrode> dead_electrodes_;
  std::vector<SwappedElectrodes> swapped_electrodes_;
  LiveStats stats_;
  std::uint64_t handled_ = 0;
  std::uint64_t last_sequence_ = 0;  ///< of the last frame handled (valid once handled_ > 0)
  std::uint64_t last_host_time_ns_ = 0;
  std::chrono::steady_clock::time_point first_, last_, previous_publish_;
  double mean_interval_s_ = 0, last_latency_s_ = 0;
  double waited_s_ = 0, reconstructing_s_ = 0, outputting_s_ = 0;  ///< totals, for LiveStats' stages
};

}  // namespace emit
