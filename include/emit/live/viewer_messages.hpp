#pragma once
/// \file viewer_messages.hpp
/// What the live server sends the viewer page (viewer/index.html reads it).
///
/// The mesh, once per client, as JSON text:
///   {"type": "mesh", "name": …, "nodes_mm": [x0, y0, x1, y1, …], "triangles": [a0, b0, c0, …],
///    "outline_mm": [xa, ya, xb, yb, …] (border edges as segments),
///    "electrodes": [{"segments_mm": [xa, ya, xb, yb, …], "x_mm": …, "y_mm": …}, …]}
/// A frame, binary: a uint32 (little-endian) byte count n, n bytes of JSON
///   {"type": "frame", "index", "sequence", "capturing_baseline", "baseline_captures", "commands",
///    "frames_per_s", "latency_ms", "max_pressure_N_per_mm2",
///    "contacts": [{"x_mm", "y_mm", "area_mm2", "pressure_N_per_mm2", "force_N"}]}
/// padded with spaces to a multiple of 4 bytes, then one float32 per triangle: the pressure [N/mm²].
/// The client answers each frame with the text "ack" (the next frame is sent only then), and may
/// send the command "recapture" (the baseline).
#include <cstdint>
#include <string>

#include "emit/live/live_loop.hpp"
#include "emit/mesh/mesh.hpp"

namespace emit {

std::string mesh_message(const Mesh& mesh, const std::string& sheet_name);

/// `commands`: how many commands the server has received so far.
std::string frame_message(const LiveFrame& frame, std::uint64_t commands);

}  // namespace emit
