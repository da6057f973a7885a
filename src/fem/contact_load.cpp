#include "emit/fem/contact_load.hpp"

namespace emit {

double ContactLoad::total_conductance_S() const {
  double total = 0;
  for (const auto& c : local_S) total += c.sum();
  return total;
}

Eigen::Matrix3d uniform_contact_matrix(double area_mm2, double conductance_S_per_mm2) {
  Eigen::Matrix3d m = Eigen::Matrix3d::Constant(1.0);
  m.diagonal().setConstant(2.0);
  return m * (conductance_S_per_mm2 * area_mm2 / 12.0);
}

ContactLoad contact_load_from_elements(const Mesh& mesh, const Vector& conductance_S_per_mm2) {
  ContactLoad load;
  for (Index t = 0; t < mesh.triangle_count(); ++t)
    if (conductance_S_per_mm2[t] != 0) {
      load.triangles.push_back(t);
      load.local_S.push_back(uniform_contact_matrix(mesh.triangle_area_mm2(t), conductance_S_per_mm2[t]));
    }
  return load;
}

}  // namespace emit
