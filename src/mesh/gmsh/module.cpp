// The Gmsh module's one export (libemit_gmsh.so; ../gmsh_mesher.hpp): its entry points.
#include "gmsh_mesher.hpp"

namespace emit::detail {

Mesh gmsh_mesh_sheet(const Sensor& sensor, const MeshOptions& flat);  // gmsh_mesh_sheet.cpp
Mesh gmsh_read_stl_sheet(const Sensor& sensor);                       // stl_sheet.cpp
Mesh gmsh_read_msh(const std::string& path);                          // msh_file.cpp
void gmsh_write_msh(const Mesh& mesh, const std::string& path);       // msh_file.cpp

}  // namespace emit::detail

// NOLINTNEXTLINE(readability-inconsistent-declaration-parameter-name): the loader's name for it
extern "C" __attribute__((visibility("default"))) const emit::detail::GmshMesher* emit_gmsh_mesher() {
  static const emit::detail::GmshMesher mesher{&emit::detail::gmsh_mesh_sheet, &emit::detail::gmsh_read_stl_sheet,
                                               &emit::detail::gmsh_read_msh, &emit::detail::gmsh_write_msh};
  return &mesher;
}
