#pragma once
/// \file viewer_messages.hpp
/// What the live server sends the viewer page (viewer/index.html reads it).
///
/// The mesh, once per client, as JSON text:
///   {"type": "mesh", "name": …, "calibrated": bool, "pressure_range_N_per_mm2": the colour bar's
///    top (0: the page's own), "adc_reference_V": the raw readings' full scale,
///    "nodes_mm": [x0, y0, x1, y1, …], "triangles": [a0, b0, c0, …],
///    "outline_mm": [xa, ya, xb, yb, …] (border edges as segments),
///    "electrodes": [{"segments_mm": [xa, ya, xb, yb, …], "x_mm": …, "y_mm": …}, …]}
/// On a curved sheet (viewer_draws_in_3d: some node has z ≠ 0) the same, and the heights beside
/// the (x, y) pairs, one z per point of the list they go with:
///   "nodes_z_mm": [z0, z1, …], "outline_z_mm": [za, zb, …],
///   each electrode's "segments_z_mm": [za, zb, …] and "z_mm" (its nodes' mean, like x_mm, y_mm);
/// a flat sheet's message has none of them (it is as it was before curved sheets).
/// A frame, binary: a uint32 (little-endian) byte count n, n bytes of JSON
///   {"type": "frame", "index", "sequence", "board_time_s", "capturing_baseline", "baseline_captures",
///    "commands", "frames_per_s", "latency_ms", "frames_missed", "misfit_mV" (< 0: no fit),
///    "readings_masked", "dead_electrodes": [{"electrode", "reason"}],
///    "swapped_electrodes": [{"electrodes": [a, b], "reason"}], "electrode_count" N,
///    "max_pressure_N_per_mm2",
///    "contacts": [{"id" (the tracker's; -1: untracked), "x_mm", "y_mm", "area_mm2", "pressure_N_per_mm2", "force_N"}]}
/// with, for a contact with an outline, its ellipse: "semi_major_mm", "semi_minor_mm",
/// "orientation_deg", and its polygon "outline_mm": [[x, y], …] in the sheet's chart (as in the
/// JSON Lines: frame/contacts.hpp; the flat view draws the polygon, else the ellipse, else the
/// circle of the area; the 3D view the ellipse's ring), and, on a curved sheet, each contact's
/// "z_mm" and unit outward "normal": [nx, ny, nz] too (the sheet's point above (x, y) and its
/// normal there: frame/contacts.hpp). Padded with spaces to a multiple of 4 bytes, then one
/// float32 per triangle: the pressure [N/mm²]; then N × N float32, the frame's readings [V] as
/// the source gave them, row by row (row l: electrode l grounded; column m: the one read).
/// The client answers each frame with the text "ack" (the next frame is sent only then), and may
/// send the command "recapture" (the no-contact reference).
#include <cstdint>
#include <string>

#include "emit/live/live_loop.hpp"
#include "emit/mesh/mesh.hpp"

namespace emit {

/// What the page says about the sheet besides its mesh.
struct ViewerSheet {
  std::string name;
  bool calibrated = false;              ///< false: the page shows an "uncalibrated" badge
  double pressure_range_N_per_mm2 = 0;  ///< the colour bar's top; 0: the page chooses
  double adc_reference_V = 0;           ///< the raw frame's full scale (sensor "adc" vref)
};

/// Whether the viewer draws this mesh in 3D (three.js): some node has z ≠ 0 (a curved sheet).
/// Flat meshes are drawn flat, on a 2D canvas.
bool viewer_draws_in_3d(const Mesh& mesh);

std::string mesh_message(const Mesh& mesh, const ViewerSheet& sheet);

/// `commands`: how many commands the server has received so far. `curved`: the mesh is drawn in
/// 3D (viewer_draws_in_3d), and the contacts carry their z and normal.
std::string frame_message(const LiveFrame& frame, std::uint64_t commands, bool curved = false);

}  // namespace emit
