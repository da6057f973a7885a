#include "emit/reconstruct/pressure.hpp"

#include <algorithm>
#include <cmath>

namespace emit {

PressureCalibration PressureCalibration::uncalibrated(const Sensor& sensor) {
  PressureCalibration c;
  c.a1 = sensor.drive_voltage_V;
  c.a2 = -1.0;
  c.a3 = 1.0 / sensor.contact.gamma;
  return c;
}

double PressureCalibration::pressure_N_per_mm2(double dphi_V) const {
  if (!(dphi_V > 0)) return 0.0;
  const double base = std::max(a1 / dphi_V + a2, 1e-9);
  return std::pow(base, a3);
}

void PressureCalibration::pressure_map(const Vector& dphi_V, double min_dphi_V, Vector& pressure,
                                       std::vector<std::uint8_t>& selected) const {
  pressure.resize(dphi_V.size());
  selected.resize(static_cast<std::size_t>(dphi_V.size()));
  const auto a1f = static_cast<float>(a1), a2f = static_cast<float>(a2), a3f = static_cast<float>(a3);
  const bool any = min_dphi_V > 0;
  for (Index k = 0; k < dphi_V.size(); ++k) {
    const bool on = any && dphi_V[k] >= min_dphi_V;
    selected[static_cast<std::size_t>(k)] = on;
    const auto dphi = static_cast<float>(dphi_V[k]);
    pressure[k] = on ? std::pow(std::max(a1f / dphi + a2f, 1e-9f), a3f) : 0.0f;
  }
}

}  // namespace emit
