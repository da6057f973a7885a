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

}  // namespace emit
