#pragma once
/// \file parameter_truth.hpp
/// A realistic sheet's truth in a sensor calibration's own terms, and how often the calibration's
/// reported σ covers it (issue "calibrate a sheet where it is used", item 4).
///
/// The calibration sees the sheet through a nominal sheet resistance: a uniform factor of the
/// sheet's conductance cannot be told from the contacts' conductances and the series resistances
/// (a frame depends on g/σ and R·σ only). So the truth of each parameter is taken as the model
/// would hold it: the twin's log-conductance over the fit mesh least-squares fitted (area-weighted)
/// by a constant c₀ and the correction's terms (θ: those terms' coefficients); a series
/// resistance R·e^{c₀}; the drive and the electrodes' shifts as drawn.
#include <vector>

#include "emit/calibrate/sensor_calibration.hpp"
#include "emit/mesh/mesh.hpp"
#include "emit/twin/realistic_sheet.hpp"

namespace emit {

/// One truth per `calibration.parameters` entry, in its unit.
std::vector<double> parameter_truth(const SensorCalibration& calibration, const RealisticSheet& sheet,
                                    const Mesh& fit_mesh);

struct ParameterCoverage {
  int parameters = 0;                          ///< compared
  int within_1_sigma = 0, within_2_sigma = 0;  ///< |value − truth| ≤ 1σ, 2σ (the reported σ)
};

/// How many of the calibration's parameters lie within 1σ and 2σ of `truth` (parameter_truth).
ParameterCoverage parameter_coverage(const SensorCalibration& calibration, const std::vector<double>& truth);

}  // namespace emit
