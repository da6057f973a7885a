#pragma once
// Private: a CAD sheet (STEP or IGES, sensor/sensor.hpp is_cad_file) brought into the current Gmsh
// session through OpenCASCADE, its electrodes the border curves the sensor names.
#include <vector>

#include "emit/sensor/sensor.hpp"

namespace emit::detail {

/// Merge the sensor's CAD file into the current Gmsh model: its surfaces are the sheet; electrode
/// i is the curve of their outer border nearest sensor.shape.electrode_at_mm[i] (within 0.5 mm),
/// a physical curve "electrode i"; its ends are appended to electrode_end_tags.
/// \throw InvalidInput naming the file and the electrode when the file holds no surface, a point
/// names no border curve, or two name the same one. \return the surfaces' area [mm²].
double import_cad_sheet(const Sensor& sensor, std::vector<int>& electrode_end_tags);

}  // namespace emit::detail
