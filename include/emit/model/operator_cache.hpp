#pragma once
/// \file operator_cache.hpp
/// The reconstruction operator (its compact form) cached on disk, keyed by everything it depends on: the sensor
/// description, the mesh itself (a hash of its nodes, triangles and electrodes), the measurement
/// set and the operator options. A second start with the same inputs loads it; a changed sensor
/// file changes the key and rebuilds it.
#include <optional>
#include <string>

#include "emit/mesh/mesh.hpp"
#include "emit/model/measurements.hpp"
#include "emit/model/reconstruction_operator.hpp"
#include "emit/sensor/sensor.hpp"

namespace emit {

/// $EMIT_CACHE_DIR, else $XDG_CACHE_HOME/emit, else $HOME/.cache/emit, else ./.emit-cache.
std::string default_cache_dir();

std::string operator_cache_key(const Sensor& sensor, const Mesh& mesh, const MeasurementSet& measurements,
                               const OperatorOptions& options);

/// The cached operator for this key, or nothing (absent, for another key, or unreadable).
std::optional<CompactOperator> load_cached_operator(const std::string& cache_dir, const std::string& key);

/// Store it (atomically; creates the folder). \throw IoError.
void store_cached_operator(const std::string& cache_dir, const std::string& key, const CompactOperator& op);

}  // namespace emit
