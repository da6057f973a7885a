#pragma once
// Private to mesh/: what meshing asks of Gmsh, in a module of its own (libemit_gmsh.so, the files
// of mesh/gmsh/) that the library loads on first use. A program that only reconstructs frames
// from a cached or given mesh then links no Gmsh, nor the OpenCASCADE, X11 and libpng it brings.
#include <string>

#include "emit/mesh/generate_mesh.hpp"
#include "emit/mesh/mesh.hpp"
#include "emit/sensor/sensor.hpp"

namespace emit::detail {

/// The module's entry points (mesh/gmsh/): each as generate_mesh.hpp, stl_sheet.hpp and
/// mesh_io.hpp describe it.
struct GmshMesher {
  /// A drawn or CAD sheet meshed by Gmsh, in the plane (a cap's disc, a cylinder's chart, not yet
  /// wrapped): generate_mesh's work once the options are checked.
  Mesh (*mesh_sheet)(const Sensor& sensor, const MeshOptions& options);
  Mesh (*read_stl_sheet)(const Sensor& sensor);
  Mesh (*read_msh)(const std::string& path);
  void (*write_msh)(const Mesh& mesh, const std::string& path);  ///< exactly at `path` (a scratch file)
};

/// The module's table, the module loaded on the first call: from emit/ beside the library (where
/// it is installed: lib/<triplet>/emit/), else the library's own folder (a build tree), else the
/// loader's search path. \throw IoError naming the module and why it could not be loaded.
const GmshMesher& gmsh_mesher();

/// What the module exports: extern "C" const GmshMesher* emit_gmsh_mesher().
inline constexpr const char* gmsh_module = "libemit_gmsh.so";
inline constexpr const char* gmsh_module_folder = "emit";  ///< installed, beside the library
inline constexpr const char* gmsh_module_entry = "emit_gmsh_mesher";

}  // namespace emit::detail
