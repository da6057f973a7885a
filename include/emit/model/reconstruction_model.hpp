#pragma once
/// \file reconstruction_model.hpp
/// The offline half of reconstruction (docs/architecture.md, the offline line): sensor → mesh → Jacobian → operator,
/// built once per sensor and method, with the operator cached on disk.
#include <functional>
#include <limits>
#include <string>
#include <vector>

#include "emit/mesh/mesh.hpp"
#include "emit/model/compact_operator.hpp"
#include "emit/model/measurements.hpp"
#include "emit/model/pressure.hpp"
#include "emit/model/reconstruction_operator.hpp"
#include "emit/sensor/sensor.hpp"

namespace emit {

struct ReconstructionModel {
  Mesh mesh;
  Shape surface;  ///< the sheet's shape: where contacts are placed in 3D (frame/contacts.hpp)
  MeasurementSet measurements;
  OperatorOptions options;  ///< with the λ² the operator was built with (chosen, when options left it 0)
  CompactOperator op;       ///< R (paper eq. 7) as the per-frame path applies it
  /// Eq. 8's uncalibrated coefficients for the model's sensor (LinearCalibration::uncalibrated):
  /// a linear method's until calibrated, and how contact fitting ranks its seeds.
  LinearCalibration uncalibrated;
  /// One reading's noise σ [V] (model/image_noise.hpp): contacts are reported only where the
  /// image stands out from the noise this puts in it. 0: no such test.
  double reading_noise_V = 0;
  /// Readings at or above this [V] are clipped (sensor/adc.hpp's clipped_at_V), so masked
  /// (frame/masked_readings.hpp). +∞: none is.
  double clipped_at_V = std::numeric_limits<double>::infinity();
  bool loaded_from_cache = false;
};

/// \param cache_dir  where to look for and store the operator; empty: no cache.
/// \param excluded   electrodes left out (dead).
/// \param progress   told each stage's name as it starts (may be empty).
ReconstructionModel build_reconstruction_model(const Sensor& sensor, const OperatorOptions& options,
                                               const std::string& cache_dir, const std::vector<int>& excluded = {},
                                               const std::function<void(const std::string&)>& progress = {});

}  // namespace emit
