#pragma once
/// \file fit_model.hpp
/// The offline half of contact fitting: its own mesh, graded into the electrodes' ends (the
/// potential is singular there; on a homogeneous mesh of the paper's size that error, ~1 % of
/// the signal, is what limits a fit: measured 0.3–0.5 mm of bias, against < 0.15 mm graded), and
/// the dense Green's function on it.
#include <functional>
#include <string>
#include <vector>

#include "emit/mesh/mesh.hpp"
#include "emit/model/green_function.hpp"
#include "emit/model/sheet_correction.hpp"
#include "emit/sensor/sensor.hpp"

namespace emit {

struct FitModel {
  Mesh mesh;
  DenseGreenFunction green;
};

/// The fit mesh alone (build_fit_model's first stage).
Mesh fit_mesh(const Sensor& sensor);

/// Its Green's function (the second stage), on the nominal sheet or, given a correction, the
/// calibrated one.
DenseGreenFunction fit_green_function(const Mesh& fit_mesh, const Sensor& sensor, const SheetCorrection* correction);

/// \param correction  the sheet's fitted resistance correction, if calibrated (else nominal)
/// \param progress    told each stage's name as it starts (may be empty).
/// \param electrode_shift_mm  each electrode's calibrated slide along the border
///                           (mesh/slide_electrodes.hpp); empty: where the sensor says.
FitModel build_fit_model(const Sensor& sensor, const SheetCorrection* correction = nullptr,
                         const std::function<void(const std::string&)>& progress = {},
                         const std::vector<double>& electrode_shift_mm = {});

}  // namespace emit
