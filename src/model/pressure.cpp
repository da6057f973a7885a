#include "emit/model/pressure.hpp"

#include <algorithm>
#include <cmath>

namespace emit {

LinearCalibration LinearCalibration::uncalibrated(const Sensor& sensor) {
  LinearCalibration c;
  c.a1 = sensor.drive_voltage_V;
  c.a2 = -1.0;
  c.a3 = 1.0 / sensor.contact.gamma;
  return c;
}

namespace {

/// Eq. 8 for δφ > 0, in the precision of `Scalar`. The base a1/δφ + a2 is kept positive (δφ
/// beyond the model's range reads as the largest pressure it can express).
template <class Scalar>
Scalar equation_8(Scalar dphi_V, Scalar a1, Scalar a2, Scalar a3) {
  return std::pow(std::max(a1 / dphi_V + a2, Scalar(1e-9)), a3);
}

}  // namespace

double LinearCalibration::pressure_N_per_mm2(double dphi_V) const {
  return dphi_V > 0 ? equation_8(dphi_V, a1, a2, a3) : 0.0;
}

void LinearCalibration::pressure_map(const Vector& dphi_V, double min_dphi_V, Vector& pressure,
                                     std::vector<std::uint8_t>& selected) const {
  pressure.resize(dphi_V.size());
  selected.resize(static_cast<std::size_t>(dphi_V.size()));
  const auto a1f = static_cast<float>(a1), a2f = static_cast<float>(a2), a3f = static_cast<float>(a3);
  const bool any = min_dphi_V > 0;
  for (Index k = 0; k < dphi_V.size(); ++k) {
    const bool on = any && dphi_V[k] >= min_dphi_V;
    selected[static_cast<std::size_t>(k)] = on;
    pressure[k] = on ? equation_8(static_cast<float>(dphi_V[k]), a1f, a2f, a3f) : 0.0f;
  }
}

}  // namespace emit
