#include "emit/render/pressure_map.hpp"

#include "emit/mesh/element_to_node.hpp"
#include "emit/render/image.hpp"
#include "emit/render/shaded_surface.hpp"

namespace emit {

bool is_curved_mesh(const Mesh& mesh) {
  return mesh.node_count() > 0 && mesh.nodes_mm.col(2).cwiseAbs().maxCoeff() > 0;
}

void write_pressure_map(const Mesh& mesh, const Vector& element_pressure, const std::vector<Circle>& outlines,
                        const std::string& title, const std::string& path) {
  FieldImageOptions image;
  image.title = title;
  image.unit = "N/mm2";
  image.min_value = 0;
  const Vector nodal = element_to_node(mesh, element_pressure);
  if (is_curved_mesh(mesh)) {
    image.width_px = shaded_pressure_map_width_px;
    write_png(render_shaded_surface(mesh, nodal, outlines, image), path);
  } else {
    write_png(render_field(mesh, nodal, outlines, image), path);
  }
}

}  // namespace emit
