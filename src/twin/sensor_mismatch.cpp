#include "emit/twin/sensor_mismatch.hpp"

#include <random>

#include "emit/core/errors.hpp"
#include "emit/mesh/slide_electrodes.hpp"

namespace emit {

Sensor with_shifted_electrodes(const Sensor& nominal, double max_shift_mm, std::uint64_t seed) {
  if (!nominal.border) throw InvalidInput("shifting electrodes needs an analytic border");
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> shift(-max_shift_mm, max_shift_mm);
  std::vector<double> shift_mm(nominal.electrodes.size());
  for (double& s : shift_mm) s = shift(rng);  // drawn in electrode order, as before
  return with_electrodes_slid(nominal, shift_mm);
}

std::vector<Mismatch> standard_mismatches(const Sensor& nominal, const TwinOptions& base, std::uint64_t seed) {
  std::vector<Mismatch> mismatches;
  Mismatch sheet{"sheet resistance +/-20 % across", nominal, base};
  sheet.twin_options.sheet_resistance_variation = 0.2;
  mismatches.push_back(sheet);
  mismatches.push_back({"electrodes shifted up to 0.5 mm", with_shifted_electrodes(nominal, 0.5, seed), base});
  Mismatch law{"contact law gamma -1.0, alpha x2", nominal, base};
  law.twin_sensor.contact.gamma = -1.0;
  law.twin_sensor.contact.alpha_ohm_mm2 *= 2;
  mismatches.push_back(law);
  // A fabric of 1 % of the probing sheet's resistance changes nothing measurable (the contact's
  // resistance, tens of kΩ, dwarfs its spreading resistance); 10 % is a poor driving layer.
  Mismatch driving{"driving layer at 10 % of Rs, fed at the bottom", nominal, base};
  driving.twin_options.driving_sheet_resistance_ohm_per_sq = 0.1 * nominal.sheet_resistance_ohm_per_sq;
  mismatches.push_back(driving);
  Mismatch dead{"electrode 5 disconnected", nominal, base};
  dead.twin_options.dead_electrode = 5;
  mismatches.push_back(dead);
  return mismatches;
}

}  // namespace emit
