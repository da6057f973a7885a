#pragma once
/// \file measurements.hpp
/// Which values of a frame the reconstruction uses: every (ground l, sense m) with l ≠ m (the
/// grounded electrode reads 0 by construction, paper §2.3), less any electrode left out (a dead
/// one: all its readings, as ground and as sense).
#include <vector>

#include "emit/core/types.hpp"

namespace emit {

struct MeasurementSet {
  int electrode_count = 0;
  std::vector<int> ground, sense;  ///< per measurement
  std::vector<int> frame_index;    ///< per measurement: l·N + m in the ground-major frame
  int size() const { return static_cast<int>(frame_index.size()); }
};

/// All l ≠ m pairs, ground-major, without the excluded electrodes.
MeasurementSet make_measurement_set(int electrode_count, const std::vector<int>& excluded_electrodes = {});

/// δV: the set's readings of `frame` less those of `reference` (both N×N, ground-major).
Vector frame_difference(const MeasurementSet& set, const Frame& frame, const Frame& reference);

}  // namespace emit
