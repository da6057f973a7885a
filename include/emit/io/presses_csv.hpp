#pragma once
/// \file presses_csv.hpp
/// Ground truth of a simulated run: `frame,x_mm,y_mm,radius_mm,force_N,pressure_N_per_mm2`, one
/// row per press (several rows share a frame index for simultaneous presses), and a 7th column
/// `profile` (flat or spherical) when some press is not flat; a row without it is flat. When some
/// press is a flat punch's outline (sensor/press_outline.hpp), an 8th column `outline`: its
/// polygons' vertices relative to (x, y), "u v;u v;…", polygons separated by '|', empty for a
/// disc; its radius_mm is then the outline's reach and its pressure force/area.
///
/// A calibration press whose place was not measured (a finger put down anywhere) leaves x_mm and
/// y_mm (and z_mm) empty; one whose force was not measured leaves force_N and the pressure empty
/// (sensor/press.hpp: NaN in memory). Only `emit calibrate` reads such rows (UnknownPresses).
#include <cstddef>
#include <ostream>
#include <string>

#include "emit/sensor/press.hpp"

namespace emit {

/// The most frames a presses file may describe when the caller does not know how many it has.
inline constexpr std::size_t default_max_press_frames = 1'000'000;

/// Written to `path` as core/output_file.hpp says. \throw IoError.
void write_presses_csv(const std::string& path, const PressSequence& sequence);
/// The same text into a stream (an opened output).
void write_presses_csv(std::ostream& out, const PressSequence& sequence);
/// Whether a reader takes presses of unknown place or force (empty fields): only calibration does.
enum class UnknownPresses { refused, allowed };

/// Presses of frames 0 … max_frames − 1 (a frame index beyond is an error, not a vector of that
/// size). Empty places and forces read as NaN where `unknowns` allows them; else "FILE:LINE: place
/// unknown: only emit calibrate takes presses without a place" (or "force unknown: …").
/// \throw IoError / InvalidInput naming the line.
PressSequence read_presses_csv(const std::string& path, std::size_t max_frames = default_max_press_frames,
                               UnknownPresses unknowns = UnknownPresses::refused);

}  // namespace emit
