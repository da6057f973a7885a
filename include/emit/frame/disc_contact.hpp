#pragma once
/// \file disc_contact.hpp
/// The contact model that contact fitting fits (docs/physics.md, "Contact fitting"): a disc
/// of centre (x, y), radius r and uniform contact conductance g per area, the twin's flat
/// indenter seen through the contact law. Its contact matrix C_ij = ∫ g s(x) φ_i φ_j dA uses an
/// indicator s smoothed over ±edge around the rim (a C¹ smoothstep), so that C, and the frame
/// predicted from it, are smooth in (x, y, r): Levenberg–Marquardt needs that, where a sharp
/// disc would make the frame jump as the rim crosses quadrature points.
#include <array>
#include <vector>

#include <Eigen/Core>

#include "emit/mesh/mesh.hpp"

namespace emit {

struct Disc {
  double x_mm = 0, y_mm = 0, radius_mm = 0;
  double conductance_S_per_mm2 = 0;
};

/// A disc's contact load: touched triangles, their 3×3 matrices [S] and, if asked, the
/// matrices' derivatives in x, y and r [S/mm] (in g it is linear: ∂C/∂g = C/g).
struct DiscLoad {
  std::vector<Index> triangles;
  std::vector<Eigen::Matrix3d> local_S;
  std::vector<std::array<Eigen::Matrix3d, 3>> d_local_S;
  void clear();
};

class DiscContactIntegrator {
 public:
  /// \param edge_mm  half-width of the smoothed rim; \param levels  subdivision depth of the
  /// quadrature on triangles the rim crosses (4^levels pieces, one point each).
  DiscContactIntegrator(const Mesh& mesh, double edge_mm, int levels = 3);

  double edge_mm() const { return edge_mm_; }

  /// Adds the disc's load to `out` (whose buffers are reused: no allocation once they are
  /// large enough). Derivatives only if `derivatives`.
  void integrate(const Disc& disc, DiscLoad& out, bool derivatives = false) const;

 private:
  struct Piece {
    Eigen::Vector3d centroid_barycentric;
    Eigen::Matrix3d integral;  ///< ∫ φ_i φ_j over the piece / the parent's area
  };
  void bucket_triangles();
  void add_triangle(std::size_t t, const Disc& disc, DiscLoad& out, bool derivatives) const;
  const Mesh* mesh_;
  double edge_mm_;
  std::vector<Piece> pieces_;
  std::vector<Vector2> centroid_mm_;
  std::vector<double> reach_mm_;  ///< farthest vertex from the centroid
  // bucket_triangles(): a grid over the centroids, cell_triangles_ listed cell by cell (row-major).
  double max_reach_mm_ = 0, cell_mm_ = 1;
  Vector2 origin_mm_;
  int columns_ = 1, rows_ = 1;
  std::vector<int> cell_start_, cell_triangles_;
};

}  // namespace emit
