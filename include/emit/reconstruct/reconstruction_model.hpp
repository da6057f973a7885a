#pragma once
/// \file reconstruction_model.hpp
/// The offline half of reconstruction (DESIGN §6): sensor → mesh → Jacobian → operator, built
/// once per sensor and method, with the operator cached on disk.
#include <functional>
#include <string>
#include <vector>

#include "emit/mesh/mesh.hpp"
#include "emit/reconstruct/compact_operator.hpp"
#include "emit/reconstruct/measurements.hpp"
#include "emit/reconstruct/reconstruction_operator.hpp"
#include "emit/sensor/sensor.hpp"

namespace emit {

struct ReconstructionModel {
  Mesh mesh;
  MeasurementSet measurements;
  OperatorOptions options;
  CompactOperator op;  ///< R (paper eq. 7) as the per-frame path applies it
  bool loaded_from_cache = false;
};

/// \param cache_dir  where to look for and store the operator; empty: no cache.
/// \param excluded   electrodes left out (dead).
/// \param progress   told each stage's name as it starts (may be empty).
ReconstructionModel build_reconstruction_model(const Sensor& sensor, const OperatorOptions& options,
                                               const std::string& cache_dir, const std::vector<int>& excluded = {},
                                               const std::function<void(const std::string&)>& progress = {});

}  // namespace emit
