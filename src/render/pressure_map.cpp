#include "emit/render/pressure_map.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "emit/mesh/element_to_node.hpp"
#include "emit/mesh/flatness.hpp"
#include "emit/render/image.hpp"
#include "emit/render/shaded_surface.hpp"
#include "emit/sensor/surface.hpp"

namespace emit {

Circle contact_outline(const Contact& c, const Shape& surface) {
  Circle mark{Vector2(c.x_mm, c.y_mm), std::sqrt(c.area_mm2 / std::numbers::pi), c.z_mm};
  if (c.semi_major_mm > 0) {
    mark.ellipse = true;
    mark.radius_mm = c.semi_major_mm;
    mark.semi_minor_mm = c.semi_minor_mm;
    mark.orientation_deg = c.orientation_deg;
  }
  for (int k = 0; k < c.outline.size; ++k) mark.polygon_mm.push_back(surface_point_mm(surface, c.outline.vertex_mm(k)));
  return mark;
}

Image render_sheet_field(const Mesh& mesh, const Vector& nodal_values, const std::vector<Circle>& outlines,
                         FieldImageOptions options) {
  if (is_flat(mesh)) return render_field(mesh, nodal_values, outlines, options);
  options.width_px = std::max(options.width_px, shaded_pressure_map_width_px);
  return render_shaded_surface(mesh, nodal_values, outlines, options);
}

void write_pressure_map(const Mesh& mesh, const Vector& element_pressure, const std::vector<Circle>& outlines,
                        const std::string& title, const std::string& path) {
  FieldImageOptions image;
  image.title = title;
  image.unit = "N/mm2";
  image.min_value = 0;
  write_png(render_sheet_field(mesh, element_to_node(mesh, element_pressure), outlines, image), path);
}

}  // namespace emit
