#pragma once
/// \file live_session.hpp
/// `emit live`: a source (live/open_source.hpp), the pipeline for a method, the live loop, and on
/// request the viewer's server, a recording and the contacts as JSON Lines, wired together.
/// Built by the constructor: every output opened first (core/output_paths.hpp's open_outputs: a
/// file's PATH.partial created, nothing replaced; one that cannot be opened touches none), then
/// the source opened and the models built; run until stopped.
///
/// Example:
///
///     emit::LiveSession session({.source = "sim", .serve = "127.0.0.1:8080"});
///     std::puts(session.viewer_url().c_str());
///     std::atomic<bool> stop{false};   // set it from a signal handler
///     const emit::LiveStats stats = session.run(stop);
#include <atomic>
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "emit/core/progress.hpp"
#include "emit/io/ros2_messages.hpp"
#include "emit/live/live_loop.hpp"
#include "emit/model/method.hpp"

namespace emit {

struct LiveJob {
  std::string source = "sim";  ///< live/open_source.hpp
  std::string serve;           ///< HOST:PORT for the viewer; empty: none
  /// The viewer's colour bar top [N/mm²], fixed; 0: the page's own (the largest pressure seen).
  double pressure_range_N_per_mm2 = 0;
  std::string contacts_path;  ///< JSON Lines; "-": standard output; a FIFO: readers may come and go; empty: none
  std::string tracks_path;    ///< tracked contacts as CSV (io/tracks_csv.hpp); empty: none
  std::string record_path;    ///< empty: no recording
  std::string mcap_path;      ///< empty: no MCAP recording (live/mcap_publisher.hpp)
  std::string dds_prefix;     ///< empty: no DDS; else the topics' prefix (live/dds_publisher.hpp)
  /// The ROS messages' header frame, on DDS and in the MCAP file (io/ros2_messages.hpp).
  std::string frame_id{ros2_frame_id};
  int dds_domain = 0;
  std::string sensor_path;       ///< empty: the built-in default sensor
  std::string calibration_path;  ///< empty: uncalibrated
  std::string cache_dir;         ///< the operator cache; empty: none
  Method method = Method::fit;
  double contact_radius_mm = 0;  ///< a declared indenter (FrameOptions::contact_radius_mm); 0: none
  std::uint64_t frames = 0;      ///< stop after this many reconstructed frames (0: no limit)
  double seconds = 0;            ///< stop after this long (0: no limit)
  double frames_per_s = 50;      ///< the simulator's pace; 0: a recording as fast as it goes
  bool loop = false;             ///< a recording starts again at its end (SourceOptions::loop)
  double reconnect_s = 30;       ///< a serial port that went away is retried this long (SourceOptions::reconnect_s)
  TrackerOptions tracking;       ///< the contacts' ids, phases, velocities (frame/contact_tracker.hpp)
};

class LiveSession {
 public:
  /// \throw InvalidInput, IoError (a source or port that cannot be opened, an unwritable file).
  explicit LiveSession(const LiveJob& job, const Progress& progress = {});
  ~LiveSession();
  LiveSession(const LiveSession&) = delete;
  LiveSession& operator=(const LiveSession&) = delete;

  std::string source_description() const;
  std::string viewer_url() const;  ///< empty when not serving
  bool calibrated() const;

  /// Runs until `stop`, the frame or time limit, the source's end, or the end of the reader of
  /// the contacts on standard output (LiveStats::contacts_reader_left); then closes the
  /// recordings and the contacts (renamed into place) and returns what the loop measured.
  /// \throw IoError (or what else the loop threw) when the source, a publisher or a writer fails.
  ///   Everything written until then is flushed and kept, but nothing is renamed: each regular
  ///   file stays PATH.partial (the recording's whole packets, an MCAP file closed whole, the
  ///   contacts' lines), so a failed run never replaces a good PATH; kept_partial() lists them
  ///   and stats() tells what the run did.
  LiveStats run(const std::atomic<bool>& stop);
  std::uint64_t recorded_frames() const;  ///< after run(); 0 without a recording
  const LiveStats& stats() const;         ///< the loop's, up to now (after a failed run: up to the failure)
  /// After run() threw: the PATH.partial files it left with what was written (empty ones are removed).
  const std::vector<std::string>& kept_partial() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace emit
