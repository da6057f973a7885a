#include "emit/eval/parameter_truth.hpp"

#include <cmath>
#include <string>

#include <Eigen/QR>

#include "emit/core/errors.hpp"

namespace emit {

namespace {

/// The electrode index in a name "…[e]".
std::size_t electrode_of(const std::string& name) { return std::stoul(name.substr(name.find('[') + 1)); }

}  // namespace

std::vector<double> parameter_truth(const SensorCalibration& calibration, const RealisticSheet& sheet,
                                    const Mesh& fit_mesh) {
  const SheetCorrection& correction = calibration.correction;
  const int K = correction.terms();
  const Index T = fit_mesh.triangle_count();
  Matrix B(T, K + 1);  // [1, b_1 … b_K], each row by √area
  Vector log_sigma(T);
  for (Index t = 0; t < T; ++t) {
    const Vector2 p = fit_mesh.triangle_centroid_mm(t).head<2>();
    const std::vector<double> b = correction.basis(p);
    const double w = std::sqrt(fit_mesh.triangle_area_mm2(t));
    B(t, 0) = w;
    for (int k = 0; k < K; ++k) B(t, k + 1) = w * b[static_cast<std::size_t>(k)];
    const double factor =
        sheet.twin_options.sheet_resistance_factor ? sheet.twin_options.sheet_resistance_factor(p) : 1.0;
    log_sigma[t] = -w * std::log(sheet.sheet_scale * factor);  // σ/σ_nominal = 1/(Rs factor)
  }
  const Vector coefficients = B.colPivHouseholderQr().solve(log_sigma);
  std::vector<double> truth;
  int theta = 0;
  for (const CalibratedParameter& p : calibration.parameters) {
    if (p.name == "drive_voltage_V") {
      truth.push_back(sheet.drive_voltage_V);
    } else if (p.name.rfind("series_resistance_ohm[", 0) == 0) {
      truth.push_back(sheet.series_ohm.at(electrode_of(p.name)) * std::exp(coefficients[0]));
    } else if (p.name.rfind("electrode_shift_mm[", 0) == 0) {
      truth.push_back(sheet.shift_mm.at(electrode_of(p.name)));
    } else if (p.name.rfind("sheet log-conductance", 0) == 0 && theta < K) {
      truth.push_back(coefficients[++theta]);
    } else {
      throw InvalidInput("parameter truth: no truth for the calibration's parameter " + p.name);
    }
  }
  return truth;
}

ParameterCoverage parameter_coverage(const SensorCalibration& calibration, const std::vector<double>& truth) {
  if (truth.size() != calibration.parameters.size())
    throw InvalidInput("parameter coverage: one truth per parameter is needed");
  ParameterCoverage coverage;
  for (std::size_t k = 0; k < truth.size(); ++k) {
    const CalibratedParameter& p = calibration.parameters[k];
    const double off = std::abs(p.value - truth[k]);
    ++coverage.parameters;
    coverage.within_1_sigma += off <= p.std;
    coverage.within_2_sigma += off <= 2 * p.std;
  }
  return coverage;
}

}  // namespace emit
