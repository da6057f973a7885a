#pragma once
/// \file flatness.hpp
/// Whether a mesh is a flat sheet (every node in the plane z = 0) or a curved one: what decides
/// a sheet's picture (render/pressure_map.hpp), the live viewer's view (live/viewer_messages.hpp),
/// and whether a sensor's mesh file can be used (mesh/generate_mesh.hpp).
#include "emit/mesh/mesh.hpp"

namespace emit {

/// Every node within 1e-9 of the mesh's extent in x and y of the plane z = 0: a flat mesh that
/// another tool wrote with heights of round-off counts as flat.
bool is_flat(const Mesh& mesh);

}  // namespace emit
