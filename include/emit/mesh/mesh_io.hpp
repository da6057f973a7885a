#pragma once
/// \file mesh_io.hpp
/// Gmsh .msh files: the sheet's triangles, and one physical curve "electrode <i>" per electrode.
#include <string>

#include "emit/mesh/mesh.hpp"

namespace emit {

/// Read a .msh file (any version Gmsh reads). Electrodes come from physical curves named
/// "electrode 0" … "electrode N-1". The mesh comes out numbered for locality (sort_for_locality.hpp).
/// \throw IoError if the file is missing; InvalidInput if it is malformed, has no triangles, or
/// lacks electrode groups.
Mesh read_msh(const std::string& path);

/// Write the mesh as .msh 4.1 via a temporary file renamed into place, so a failed write never
/// leaves a half file over a good one. \throw IoError.
void write_msh(const Mesh& mesh, const std::string& path);

}  // namespace emit
