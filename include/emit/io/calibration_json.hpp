#pragma once
/// \file calibration_json.hpp
/// Pressure calibration files, as `emit calibrate` writes them: {"a1": …, "a2": …, "a3": …}
/// (paper eq. 8) for the linear methods, {"alpha_ohm_mm2": …, "gamma": …} (eq. 2 as the fit
/// sees it) for contact fitting; other keys are errors.
#include <string>

#include "emit/model/calibration.hpp"

namespace emit {

/// The kind is told by the keys. \throw IoError if unreadable; InvalidInput naming the key.
Calibration load_calibration(const std::string& path);
/// Written via a temporary file renamed into place. \throw IoError.
void write_calibration(const std::string& path, const Calibration& calibration);

}  // namespace emit
