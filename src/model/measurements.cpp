#include "emit/model/measurements.hpp"

#include <algorithm>

namespace emit {

MeasurementSet make_measurement_set(int electrode_count, const std::vector<int>& excluded_electrodes) {
  MeasurementSet set;
  set.electrode_count = electrode_count;
  auto excluded = [&](int e) {
    return std::find(excluded_electrodes.begin(), excluded_electrodes.end(), e) != excluded_electrodes.end();
  };
  for (int l = 0; l < electrode_count; ++l)
    for (int m = 0; m < electrode_count; ++m)
      if (l != m && !excluded(l) && !excluded(m)) {
        set.ground.push_back(l);
        set.sense.push_back(m);
        set.frame_index.push_back(l * electrode_count + m);
      }
  return set;
}

Vector frame_difference(const MeasurementSet& set, const Frame& frame, const Frame& reference) {
  Vector dV(set.size());
  for (int i = 0; i < set.size(); ++i)
    dV[i] = frame.data()[set.frame_index[static_cast<std::size_t>(i)]] -
            reference.data()[set.frame_index[static_cast<std::size_t>(i)]];
  return dV;
}

}  // namespace emit
