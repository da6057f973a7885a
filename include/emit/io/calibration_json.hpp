#pragma once
/// \file calibration_json.hpp
/// Pressure calibration files: {"a1": …, "a2": …, "a3": …} (paper eq. 8), as `emit calibrate`
/// writes them; other keys are errors.
#include <string>

#include "emit/reconstruct/pressure.hpp"

namespace emit {

/// \throw IoError if unreadable; InvalidInput naming the key.
PressureCalibration load_calibration(const std::string& path);
void write_calibration(const std::string& path, const PressureCalibration& calibration);

}  // namespace emit
