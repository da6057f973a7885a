#pragma once
/// \file calibration_json.hpp
/// Pressure calibration files, as `emit calibrate` writes them: {"a1": …, "a2": …, "a3": …}
/// (paper eq. 8) for the linear methods, with "force_law": {"b1_V_mm2", "b2", "b3", "log_std",
/// "indenter_radius_mm"} (emit's force from the image's integral, model/force_law.hpp; a file
/// written before it loads without one, its contacts' force and area then the image's);
/// {"alpha_ohm_mm2": …, "gamma": …} (eq. 2 as the fit sees it, with the sheet's correction, the
/// drive voltage, the series resistances and the sensor it was made for) for contact fitting;
/// other keys are errors. A contact-fitting file may carry a "report" (what the sensor calibration
/// found, with uncertainties and its goodness of fit), for people: it is not read back.
#include <ostream>
#include <string>

#include "emit/calibrate/sensor_calibration.hpp"
#include "emit/model/calibration.hpp"

namespace emit {

/// The kind is told by the keys. \throw IoError if unreadable; InvalidInput naming the key.
Calibration load_calibration(const std::string& path);
/// Written to `path` as core/output_file.hpp says (a file via a temporary file renamed into
/// place). `report`, if given, is written as "report". \throw IoError.
void write_calibration(const std::string& path, const Calibration& calibration,
                       const SensorCalibration* report = nullptr);
/// The same JSON into a stream (an opened output).
void write_calibration(std::ostream& out, const Calibration& calibration, const SensorCalibration* report = nullptr);

}  // namespace emit
