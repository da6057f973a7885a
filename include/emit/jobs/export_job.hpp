#pragma once
/// \file export_job.hpp
/// `emit export`: a recording (acquire/recording.hpp, `emit live --record`) turned into the files
/// the other commands read and write, so a live run can be calibrated, reconstructed again or
/// played in ROS 2 after the fact:
///
/// - frames: every frame of the recording, in order, as a frames CSV (io/frames_csv.hpp), the
///   volts the live run saw (counts × the recording's own ADC reference, file_source.hpp). The
///   format has no room for times (N·N numbers a line, nothing else; its readers refuse more), so
///   the board's times are not in it: they are in the contacts and the MCAP file.
/// - reference: the recording's first `reference_frames` frames (the no-contact frames `emit live`
///   captured its reference from, 10 by default as there) as a frames CSV, what `--reference`
///   reads. They stay in the frames too: line f of the frames is frame f of the recording, always.
/// - contacts: every frame reconstructed as `emit reconstruct --reference R --frames F` would with
///   those two files (the reference's robust mean, held fixed; dead electrodes found over the
///   whole recording and left out), tracked on the board's clock, one JSON line per frame
///   (io/contacts_jsonl.hpp): "frame" is the frame's index in the recording (its line in the
///   frames CSV), "board_time_s" the board's time. No "host_time_s": a recording does not hold
///   when each frame reached the host. The same contacts as tracks CSV (io/tracks_csv.hpp).
/// - mcap: the same frames, contacts and pressure images as an MCAP file (io/tactile_mcap.hpp),
///   stamped with the recording's start (its header) plus the board's time since its first frame.
///
/// Every output is opened before the recording is read (core/output_paths.hpp: none may be an
/// input) and grows as PATH.partial, renamed to PATH when the whole recording is exported. A
/// recording that is cut (a crashed run's REC.partial) or holds a corrupt packet is exported up to
/// it, then the job fails naming it: the outputs then stay PATH.partial, PATH untouched, as
/// `emit live` leaves its files when its source fails.
#include <cstdint>
#include <string>
#include <vector>

#include "emit/core/progress.hpp"
#include "emit/frame/contact_tracker.hpp"
#include "emit/model/method.hpp"

namespace emit {

struct ExportJob {
  std::string recording_path;    ///< the recording (required)
  std::string frames_path;       ///< every frame as CSV; empty: none
  std::string reference_path;    ///< the first reference_frames frames as CSV; empty: none
  int reference_frames = 10;     ///< the reference's frames, from the recording's start (as `emit live` captures)
  std::string contacts_path;     ///< contacts as JSON Lines; "-": standard output; empty: none
  std::string tracks_path;       ///< the tracked contacts as CSV (io/tracks_csv.hpp), time the board's; empty: none
  std::string mcap_path;         ///< frames, contacts and pressure images as MCAP; empty: none
  std::string sensor_path;       ///< empty: the built-in default sensor
  std::string calibration_path;  ///< empty: uncalibrated (contacts and mcap only)
  std::string cache_dir;         ///< the operator cache; empty: none
  Method method = Method::fit;
  double contact_radius_mm = 0;  ///< a declared indenter (FrameOptions::contact_radius_mm); 0: none
  TrackerOptions tracking;       ///< the contacts' ids, phases and velocities (frame/contact_tracker.hpp)

  bool reconstructs() const { return !contacts_path.empty() || !tracks_path.empty() || !mcap_path.empty(); }
  /// \throw InvalidInput: no output asked for; reference_frames below 1; --calibration without
  ///   --contacts, --tracks or --mcap (nothing would use it); the tracking's options.
  void validate() const;
};

struct ExportReport {
  std::uint64_t frames = 0;            ///< exported (every frame of the recording)
  std::uint64_t reference_frames = 0;  ///< in the reference file, and the contacts' reference
  double board_seconds = 0;            ///< from the first frame to the last, on the board's clock
  std::uint64_t frames_missed =
      0;  ///< gaps in the recording's sequence numbers (frames the board sent but the run lost)
  bool calibrated = false;
  long triangles = 0;                ///< the reconstruction mesh's (0 without contacts or mcap)
  std::vector<int> dead_electrodes;  ///< left out of the reconstruction (each also told to progress.warning)
  double seconds = 0;                ///< the export's time, model building included
};

/// \throw InvalidInput (ExportJob::validate; not a recording; another electrode count than the
///   sensor's; fewer frames than the reference needs), IoError (a cut or corrupt recording, after
///   the frames before it are exported: the message says where they are), SolverError.
ExportReport run_export_job(const ExportJob& job, const Progress& progress = {});

}  // namespace emit
