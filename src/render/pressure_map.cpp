#include "emit/render/pressure_map.hpp"

#include "emit/mesh/element_to_node.hpp"
#include "emit/render/image.hpp"

namespace emit {

void write_pressure_map(const Mesh& mesh, const Vector& element_pressure, const std::vector<Circle>& outlines,
                        const std::string& title, const std::string& path) {
  FieldImageOptions image;
  image.title = title;
  image.unit = "N/mm2";
  image.min_value = 0;
  write_png(render_field(mesh, element_to_node(mesh, element_pressure), outlines, image), path);
}

}  // namespace emit
