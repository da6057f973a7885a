#pragma once
/// \file mesh_io.hpp
/// Gmsh .msh files: the sheet's triangles, and one physical curve "electrode <i>" per electrode.
#include <string>

#include "emit/core/output_file.hpp"
#include "emit/mesh/mesh.hpp"
#include "emit/sensor/sensor.hpp"

namespace emit {

/// Read a .msh file (version 4.1 or 2.2, ASCII or binary), checked by emit before Gmsh reads it
/// (msh_file_check.hpp: counts, finite coordinates, at most max_triangles triangles), and its
/// triangles then checked to have an area. Electrodes come from physical curves named
/// "electrode 0" … "electrode N-1". The mesh comes out numbered for locality (sort_for_locality.hpp).
/// \throw IoError if the file is missing; InvalidInput naming the file if it is malformed, has no
/// triangles or more than max_triangles, a triangle of zero area, or lacks electrode groups.
Mesh read_msh(const std::string& path, double max_triangles = MeshSpec{}.max_triangles);

/// Write the mesh as .msh 4.1 into an opened output (core/output_file.hpp: a regular file through
/// a temporary file renamed on the caller's commit(), a device or FIFO written into). Gmsh writes
/// only to files it names and picks the format from the name, so it writes a scratch file in a
/// private temporary folder, which is copied into the output and removed. \throw IoError.
void write_msh(const Mesh& mesh, OutputFile& out);
/// The same into `path`, committed. \throw IoError.
void write_msh(const Mesh& mesh, const std::string& path);

}  // namespace emit
