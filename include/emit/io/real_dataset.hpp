#pragma once
/// \file real_dataset.hpp
/// A real skin's measured presses, in a folder laid out as README "Current-injection skins
/// on real data" says:
///   frames.csv                  one pressed frame per line, M values (comma-separated, no header)
///   references_per_frame.csv    line i: the unpressed frame measured just before press i
///   (or reference.csv)          one unpressed frame for them all, when there is no per-frame one
///   truth.csv                   header frame,contact,x_mm,y_mm[,...]: where each frame was pressed
///                               (more columns, such as depth_mm, are kept unread)
/// Every value of a frame must be a number (`nan` and `inf` are read: a board's dropped samples,
/// masked by the evaluation, model/reading_screen.hpp); every frame the same length.
#include <cstddef>
#include <string>
#include <vector>

#include "emit/core/types.hpp"

namespace emit {

struct RealDataset {
  std::string folder;
  Matrix frames;      ///< presses × M
  Matrix references;  ///< presses × M: each press's unpressed frame
  bool per_frame_references = false;
  /// contacts[i]: the centres of frame i's presses [mm] (empty: a frame with no press listed).
  std::vector<std::vector<Vector2>> contacts;

  Index presses() const { return frames.rows(); }
  Index readings() const { return frames.cols(); }
};

/// The most values a folder's frames may hold, frames × M: 2^27, 1 GiB of doubles.
inline constexpr std::size_t max_real_dataset_values = std::size_t{1} << 27;

/// \throw IoError for a missing file, InvalidInput for a malformed one, naming "<path>:<line>".
/// max_values bounds frames × M (the memory a folder may take).
RealDataset read_real_dataset(const std::string& folder, std::size_t max_values = max_real_dataset_values);

}  // namespace emit
