#pragma once
/// \file calibration_json.hpp
/// Pressure calibration files, as `emit calibrate` writes them: {"a1": …, "a2": …, "a3": …}
/// (paper eq. 8) for the linear methods, {"alpha_ohm_mm2": …, "gamma": …} (eq. 2 as the fit
/// sees it) for contact fitting; other keys are errors.
#include <string>

#include "emit/reconstruct/pressure.hpp"

namespace emit {

/// \throw IoError if unreadable; InvalidInput naming the key.
PressureCalibration load_calibration(const std::string& path);
void write_calibration(const std::string& path, const PressureCalibration& calibration);

}  // namespace emit
