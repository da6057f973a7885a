// Gmsh .msh files read and written by Gmsh (mesh/mesh_io.hpp, through ../gmsh_mesher.hpp).
#include <gmsh.h>

#include "emit/core/errors.hpp"
#include "gmsh_mesher.hpp"
#include "gmsh_session.hpp"
#include "sheet_file_access.hpp"

namespace emit::detail {

Mesh gmsh_read_msh(const std::string& path) {
  check_sheet_file_access(path, "mesh file");
  GmshSession gmsh_session;
  gmsh_session.run<InvalidInput>(path + ": not a valid Gmsh mesh", [&] { gmsh::open(path); });
  return gmsh_session.extract_mesh(path);
}

void gmsh_write_msh(const Mesh& mesh, const std::string& path) {
  GmshSession gmsh_session;
  gmsh_session.run<IoError>(path + ": cannot write mesh", [&] {
    gmsh::model::add("emit");
    const int surface = gmsh::model::addDiscreteEntity(2);
    std::vector<std::size_t> node_tags(static_cast<std::size_t>(mesh.node_count()));
    std::vector<double> coords;
    for (Index v = 0; v < mesh.node_count(); ++v) {
      node_tags[v] = static_cast<std::size_t>(v + 1);
      for (int c = 0; c < 3; ++c) coords.push_back(mesh.nodes_mm(v, c));
    }
    gmsh::model::mesh::addNodes(2, surface, node_tags, coords);
    std::vector<std::size_t> triangle_tags, triangle_nodes;
    for (Index t = 0; t < mesh.triangle_count(); ++t) {
      triangle_tags.push_back(static_cast<std::size_t>(t + 1));
      for (int k = 0; k < 3; ++k) triangle_nodes.push_back(static_cast<std::size_t>(mesh.triangles(t, k) + 1));
    }
    gmsh::model::mesh::addElementsByType(surface, 2, triangle_tags, triangle_nodes);
    gmsh::model::setPhysicalName(2, gmsh::model::addPhysicalGroup(2, {surface}), "sheet");
    std::size_t next_tag = triangle_tags.size() + 1;
    for (int e = 0; e < mesh.electrode_count(); ++e) {
      const int curve = gmsh::model::addDiscreteEntity(1);
      std::vector<std::size_t> line_tags, line_nodes;
      for (const auto& edge : mesh.electrode_edges(e)) {
        line_tags.push_back(next_tag++);
        line_nodes.push_back(static_cast<std::size_t>(edge[0] + 1));
        line_nodes.push_back(static_cast<std::size_t>(edge[1] + 1));
      }
      gmsh::model::mesh::addElementsByType(curve, 1, line_tags, line_nodes);
      gmsh::model::setPhysicalName(1, gmsh::model::addPhysicalGroup(1, {curve}), "electrode " + std::to_string(e));
    }
    gmsh::option::setNumber("Mesh.MshFileVersion", 4.1);
    gmsh::write(path);
  });
}

}  // namespace emit::detail
