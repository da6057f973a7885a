#include "emit/render/pressure_map.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <numbers>

#include "emit/core/option_check.hpp"
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

void PressureMapOptions::validate() const {
  option_check::non_negative("PressureMapOptions", "max_pressure_N_per_mm2", max_pressure_N_per_mm2);
  option_check::within("PressureMapOptions", "width_px", width_px, 160, 8192);
}

void write_pressure_map(const Mesh& mesh, const Vector& element_pressure, const std::vector<Circle>& outlines,
                        const std::string& title, const std::string& path, const PressureMapOptions& options) {
  options.validate();
  FieldImageOptions image;
  image.title = title;
  image.unit = "N/mm2";
  image.width_px = options.width_px;
  image.min_value = 0;
  if (options.max_pressure_N_per_mm2 > 0) image.max_value = options.max_pressure_N_per_mm2;
  write_png(render_sheet_field(mesh, element_to_node(mesh, element_pressure), outlines, image), path);
}

std::string contact_label(const Contact& contact) {
  std::array<char, 64> text{};
  if (contact.id >= 0)
    std::snprintf(text.data(), text.size(), "#%lld  %.1f N", static_cast<long long>(contact.id), contact.force_N);
  else std::snprintf(text.data(), text.size(), "%.1f N", contact.force_N);
  return text.data();
}

std::string frame_image_name(std::size_t frame) {
  std::array<char, 32> name{};
  std::snprintf(name.data(), name.size(), "frame_%06zu.png", frame);
  return name.data();
}

}  // namespace emit
