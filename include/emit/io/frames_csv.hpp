#pragma once
/// \file frames_csv.hpp
/// Frames as CSV (README, "Files"): one frame per line, N·N comma-separated volts, ground-major
/// (index l·N + m), no header.
#include <string>
#include <vector>

#include "emit/core/types.hpp"

namespace emit {

/// Write all frames (each N×N), replacing `path` only when the whole file is written.
void write_frames_csv(const std::string& path, const std::vector<Frame>& frames);

/// Read frames of `electrode_count` electrodes. \throw IoError if unreadable; InvalidInput
/// naming the line and value for a wrong value count, text, NaN or infinity.
std::vector<Frame> read_frames_csv(const std::string& path, int electrode_count);

}  // namespace emit
