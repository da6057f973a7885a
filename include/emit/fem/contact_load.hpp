#pragma once
/// \file contact_load.hpp
/// The contact term of the forward model (docs/physics.md, "Forward model"): C_ij = ∫ g φ_i φ_j dA, g the contact
/// conductance per area [S/mm²] coupling the probing sheet to the driving layer. Stored per
/// touched element, so a press touching a few hundred triangles costs that, not the mesh.
#include <vector>

#include <Eigen/Core>

#include "emit/mesh/mesh.hpp"

namespace emit {

struct ContactLoad {
  std::vector<Index> triangles;          ///< touched triangles
  std::vector<Eigen::Matrix3d> local_S;  ///< their 3×3 contact matrices [S]
  bool empty() const { return triangles.empty(); }
  /// Total contact conductance Σ C_ij [S] (= ∫ g dA).
  double total_conductance_S() const;
};

/// Local contact matrix of a triangle with uniform conductance g: g·A/12·[2 1 1; 1 2 1; 1 1 2].
Eigen::Matrix3d uniform_contact_matrix(double area_mm2, double conductance_S_per_mm2);

/// A contact load with uniform conductance per triangle (zero entries skipped).
ContactLoad contact_load_from_elements(const Mesh& mesh, const Vector& conductance_S_per_mm2);

}  // namespace emit
