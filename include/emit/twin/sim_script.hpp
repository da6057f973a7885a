#pragma once
/// \file sim_script.hpp
/// What the simulated finger of `emit live --source sim…` presses, frame by frame: a pure
/// function of the script, the sheet and the frame's number (ScriptedPresses::presses_of), so the
/// twin's source (twin/sim_source.hpp) and the tests that check it agree on the truth.
///
/// The scripts stay on the sheet. The figure-eight goes round the middle of the sheet's chart box,
/// as far as 0.55 and 0.4 of its half sizes, shrunk (by 0.9 at a time) until every point of it
/// keeps the indenter's radius + 3 mm from the border (in 3D: room_mm); the random presses keep
/// the same margin; "sim:fixed" holds a press at the middle. A sheet whose middle has no such room
/// is refused at the start, naming it, rather than failing mid-run. A sleeve's seam is no border
/// (a press across it loads both sides, twin/press_contact.hpp).
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "emit/acquire/frame_source.hpp"
#include "emit/mesh/mesh.hpp"
#include "emit/sensor/press.hpp"
#include "emit/sensor/sensor.hpp"
#include "emit/twin/calibration_person.hpp"

namespace emit {

/// What the simulated finger does.
struct SimScript {
  enum class Kind {
    loop,    ///< a figure-eight over the sheet, 6 s pressed then 1 s lifted, again and again
    random,  ///< a press at a random place for 0.6 s, then 0.2 s lifted, again and again
    fixed,   ///< one press held: `fixed`, a disc or an outline
    /// a person calibrating without a robot (twin/calibration_person.hpp): quiet, `person.presses`
    /// finger presses at random places, then the known weights; then lifted for good
    calibration,
  };
  Kind kind = Kind::loop;
  Press fixed{30, 30, 5, 10};               ///< kind fixed: where and how hard
  bool fixed_at_middle = false;             ///< kind fixed: at the sheet's middle instead ("sim:fixed")
  double radius_mm = 5;                     ///< the indenter of loop and random
  double min_force_N = 2, max_force_N = 8;  ///< loop: force swings between them; random: drawn uniformly
  CalibrationPersonOptions person;          ///< kind calibration (its seed: the source's)
};

/// "sim", "sim:loop", "sim:random", "sim:calibration[:PRESSES]" (a person calibrating: PRESSES finger
/// presses, default 60, then the default weights), "sim:fixed" (10 N held at the sheet's middle), "sim:fixed:X,Y[,F]",
/// or "sim:fixed:OUTLINE": a flat punch of any outline `emit simulate --press` takes (bar:x,y,L,W,angle,F, ellipse:…,
/// ring:…, polygon:…; flat sheets only: sensor/press_outline.hpp), held. \throw InvalidInput naming the spec.
SimScript parse_sim_script(const std::string& spec);

/// A script on a sheet: the presses of every frame.
class ScriptedPresses {
 public:
  /// `sensor` and `mesh` (the twin's) must outlive this. Uses options' frames_per_s (the
  /// scripts' clock; unpaced: 50 frames/s), untouched_frames and seed.
  /// \throw InvalidInput for a fixed press off the sheet, a sheet whose middle is within the
  ///   margin of its border (the figure-eight, sim:fixed), or bad options.
  ScriptedPresses(const Sensor& sensor, const Mesh& mesh, SimScript script, const SourceOptions& options);

  /// The presses for frame `sequence` (empty: nothing touches), each centred on the surface.
  std::vector<Press> presses_of(std::uint64_t sequence) const;
  const SimScript& script() const { return script_; }
  /// The scripts' clock: frame k at (k − untouched) / frames_per_s (the pace its source runs at;
  /// 0: 50 frames/s), so the finger moves as fast in seconds at any pace.
  void set_frames_per_s(double frames_per_s) { options_.frames_per_s = frames_per_s; }
  /// How much of its full reach the figure-eight has on this sheet (1: all of it).
  double loop_scale() const { return loop_scale_; }
  /// "a finger moving in a figure-eight", "a press held at (30, 30) mm, 10 N", …
  std::string description() const;

  /// Every scripted press's centre keeps the indenter's radius and this much more from the border
  /// (room_mm): all of its disc is on the sheet, with room to spare.
  static constexpr double margin_mm = 3;
  /// How far the surface's point at this chart point is from the sheet's border: the 3D distance
  /// to the nearest of the border's points on the surface (sampled every 0.25 mm), since a press
  /// loads what is within its radius in 3D (twin/press_contact.hpp); a sleeve's, along its axis
  /// (its seam is no border); negative off the sheet; a mesh file's sheet without an outline:
  /// infinite on its mesh.
  double room_mm(const Vector2& chart_mm) const;

 private:
  double script_time_s(std::uint64_t sequence) const;
  /// The figure-eight's chart point at phase w, `scale` of its full reach.
  Vector2 loop_point(double w, double scale) const;
  /// The script's press of this force at chart point p (sensor/surface.hpp).
  Press press_at(const Vector2& chart_mm, double force_N) const;

  const Sensor& sensor_;
  const Mesh& mesh_;
  SimScript script_;
  SourceOptions options_;
  Vector2 center_mm_, half_extent_mm_;       ///< of the sheet's chart box, for the loop's path
  double loop_scale_ = 1;                    ///< of the figure-eight's full reach, as the sheet has room
  std::vector<Vector3> border_points_mm_;    ///< the border on the surface (room_mm)
  std::optional<CalibrationPerson> person_;  ///< kind calibration: the session, drawn once
};

}  // namespace emit
