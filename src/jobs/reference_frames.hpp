#pragma once
// Private to jobs/: the no-contact reference a job reads from a CSV file, checked.
#include <string>

#include "emit/core/progress.hpp"
#include "emit/frame/reference.hpp"
#include "emit/sensor/sensor.hpp"

namespace emit::detail {

/// The robust average of the file's frames (frame/reference.hpp), each in the ADC's range
/// (check_readings_in_range); a warning through `progress` if it looks pressed (a no-contact
/// frame reads about 0 V). \throw InvalidInput naming the file (no frames, a bad value), IoError.
Reference read_reference(const std::string& path, const Sensor& sensor, int electrode_count, const Progress& progress);

}  // namespace emit::detail
