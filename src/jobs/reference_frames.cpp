#include "reference_frames.hpp"

#include <vector>

#include "emit/acquire/electrode_health.hpp"
#include "emit/frame/reference.hpp"
#include "emit/io/frames_csv.hpp"

namespace emit::detail {

Reference read_reference(const std::string& path, const Sensor& sensor, int electrode_count, const Progress& progress) {
  const std::vector<Frame> frames = read_frames_csv(path, electrode_count, true);
  for (std::size_t f = 0; f < frames.size(); ++f)
    check_readings_in_range(frames[f], sensor.adc, path + ": frame " + std::to_string(f));
  Reference reference = average_reference(frames);
  if (looks_pressed(reference.frame, sensor.adc))
    progress.warn(path + ": the reference reads up to " + std::to_string(reference.frame.maxCoeff()) +
                  " V, where a frame without contact reads about 0 V: was the sheet pressed?");
  return reference;
}

}  // namespace emit::detail
