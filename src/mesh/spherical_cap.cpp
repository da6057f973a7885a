#include "emit/mesh/spherical_cap.hpp"

#include <algorithm>
#include <cmath>

namespace emit {

double spherical_cap_stretch(double sphere_radius_mm, double base_radius_mm) {
  return sphere_radius_mm * std::asin(std::min(1.0, base_radius_mm / sphere_radius_mm)) / base_radius_mm;
}

Vector3 spherical_cap_point_mm(const Vector3& flat_mm, double sphere_radius_mm, double base_radius_mm) {
  const double R = sphere_radius_mm, a = base_radius_mm;
  const double rim_rad = std::asin(std::min(1.0, a / R));
  const double rho = std::hypot(flat_mm.x(), flat_mm.y());
  // On the rim exactly: its nodes stay where the electrodes put them.
  if (rho >= a) return {flat_mm.x() * a / rho, flat_mm.y() * a / rho, 0};
  const double theta = rim_rad * rho / a;
  const double from_axis = R * std::sin(theta);
  const double scale = rho > 0 ? from_axis / rho : 0;
  return {flat_mm.x() * scale, flat_mm.y() * scale, R * (std::cos(theta) - std::cos(rim_rad))};
}

void wrap_onto_spherical_cap(Mesh& mesh, double sphere_radius_mm, double base_radius_mm) {
  for (Index v = 0; v < mesh.node_count(); ++v)
    mesh.nodes_mm.row(v) =
        spherical_cap_point_mm(mesh.nodes_mm.row(v).transpose(), sphere_radius_mm, base_radius_mm).transpose();
}

}  // namespace emit
