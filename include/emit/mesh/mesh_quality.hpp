#pragma once
/// \file mesh_quality.hpp
/// Numbers that say whether a mesh is fit for the FEM: counts, angles, sizes.
#include "emit/mesh/mesh.hpp"

namespace emit {

struct MeshQuality {
  Index node_count = 0;
  Index triangle_count = 0;
  double min_angle_deg = 0;  ///< smallest interior angle over all triangles
  double mean_edge_mm = 0;
  double min_area_mm2 = 0;
  double total_area_mm2 = 0;
};

MeshQuality measure_mesh_quality(const Mesh& mesh);

}  // namespace emit
