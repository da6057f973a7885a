#include "emit/model/sheet_correction.hpp"

#include <algorithm>
#include <cmath>

namespace emit {

SheetCorrection SheetCorrection::identity_over(const Mesh& mesh, int terms) {
  SheetCorrection c;
  c.log_conductance.assign(static_cast<std::size_t>(terms == cubic_terms ? cubic_terms : quadratic_terms), 0.0);
  c.lower_mm = mesh.nodes_mm.leftCols<2>().colwise().minCoeff().transpose();
  c.upper_mm = mesh.nodes_mm.leftCols<2>().colwise().maxCoeff().transpose();
  return c;
}

std::vector<double> SheetCorrection::basis(const Vector2& point_mm) const {
  const Vector2 uv = (2 * (point_mm - lower_mm).array() / (upper_mm - lower_mm).array() - 1).matrix();
  const double u = uv.x(), v = uv.y();
  if (terms() == cubic_terms) return {u, v, u * u, u * v, v * v, u * u * u, u * u * v, u * v * v, v * v * v};
  return {u, v, u * u, u * v, v * v};
}

double SheetCorrection::factor(const Vector2& point_mm) const {
  const auto b = basis(point_mm);
  double exponent = 0;
  for (int k = 0; k < terms(); ++k)
    exponent += log_conductance[static_cast<std::size_t>(k)] * b[static_cast<std::size_t>(k)];
  return std::exp(exponent);
}

Vector SheetCorrection::element_conductance_S(const Mesh& mesh, double sheet_resistance_ohm_per_sq) const {
  Vector conductance(mesh.triangle_count());
  for (Index t = 0; t < mesh.triangle_count(); ++t)
    conductance[t] = factor(mesh.triangle_centroid_mm(t).head<2>()) / sheet_resistance_ohm_per_sq;
  return conductance;
}

std::pair<double, double> SheetCorrection::factor_range(const Mesh& mesh) const {
  double low = INFINITY, high = 0;
  for (Index t = 0; t < mesh.triangle_count(); ++t) {
    const double f = factor(mesh.triangle_centroid_mm(t).head<2>());
    low = std::min(low, f), high = std::max(high, f);
  }
  return {low, high};
}

}  // namespace emit
