#pragma once
/// \file calibration.hpp
/// emit.Calibration as the bindings hold it: the calibration, and how well it fitted its presses
/// when it was made here (a file read back carries no such figures).
#include <cstddef>
#include <optional>

#include "emit/model/calibration.hpp"

namespace emit::python {

struct PythonCalibration {
  Calibration calibration;
  std::size_t presses = 0;              ///< single presses it was fitted on (0: read from a file)
  std::optional<double> rms_N_per_mm2;  ///< the calibrated pressure's error over them
  std::optional<double> max_abs_N_per_mm2;
};

/// The library's optional calibration, from Python's (None or an emit.Calibration).
inline std::optional<Calibration> calibration_of(const std::optional<PythonCalibration>& given) {
  if (!given) return std::nullopt;
  return given->calibration;
}

}  // namespace emit::python
