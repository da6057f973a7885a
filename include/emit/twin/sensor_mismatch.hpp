#pragma once
/// \file sensor_mismatch.hpp
/// Real sheets differ from their description. Each mismatch is a twin that departs from the
/// nominal sensor in one way, while the reconstruction keeps the nominal description.
#include <cstdint>
#include <string>
#include <vector>

#include "emit/twin/twin.hpp"

namespace emit {

struct Mismatch {
  std::string name;
  Sensor twin_sensor;  ///< what the twin simulates
  TwinOptions twin_options;
};

/// The sensor with each electrode moved along the border by a uniform random amount in
/// [−max_shift_mm, max_shift_mm].
Sensor with_shifted_electrodes(const Sensor& nominal, double max_shift_mm, std::uint64_t seed);

/// Sheet resistance ±20 % across the sheet; electrodes shifted by up to 0.5 mm; another contact
/// law (γ = −1.0, α doubled); a driving layer of 10 % of the probing sheet's resistance, fed at
/// the bottom; a dead electrode (number 5). `base` carries the mesh seed and noise.
std::vector<Mismatch> standard_mismatches(const Sensor& nominal, const TwinOptions& base, std::uint64_t seed);

}  // namespace emit
