#pragma once
/// \file disc_contact.hpp
/// The contact model that contact fitting fits (docs/physics.md, "Contact fitting"): a disc
/// of centre (x, y), radius r and uniform contact conductance g per area, the twin's flat
/// indenter seen through the contact law. Its contact matrix C_ij = ∫ g s(x) φ_i φ_j dA uses an
/// indicator s smoothed over ±edge around the rim (a C¹ smoothstep), so that C, and the frame
/// predicted from it, are smooth in (x, y, r): Levenberg–Marquardt needs that, where a sharp
/// disc would make the frame jump as the rim crosses quadrature points.
///
/// On a curved sheet (sensor/surface.hpp) the disc is the part of the surface within 3D distance
/// r of its centre, the surface's point above (x, y): a chord, not a geodesic, radius. For the
/// held radius (2 mm) on the 25 mm dome the two differ by r³/(24 R²) < 0.001 mm, far below the
/// mesh's facets' own distance from the sphere (h²/8R ≈ 0.004 mm), and the chord needs no
/// geodesics on the mesh. The centre stays named by (x, y), so the fit's parameters, seeds and
/// bounds are the flat sheet's.
#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

#include <Eigen/Core>

#include "emit/mesh/mesh.hpp"
#include "emit/sensor/sensor.hpp"

namespace emit {

struct Disc {
  /// The centre's chart point (sensor/surface.hpp): (x, y) on a flat sheet and a cap; along the
  /// axis and around it on a cylinder.
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

/// The rim's smoothed indicator, disc and ellipse alike: a C¹ smoothstep of ξ = (R − d)/edge over
/// [−1, 1] (0 outside, 1 inside), and its derivative in ξ.
void rim_smoothstep(double xi, double& s, double& ds_dxi);
/// ∫ φ_i φ_j over a triangle per unit area: (1 + δ_ij)/12.
Eigen::Matrix3d uniform_integral();

class DiscContactIntegrator {
 public:
  /// \param edge_mm  half-width of the smoothed rim; \param levels  subdivision depth of the
  /// quadrature on triangles the rim crosses (4^levels pieces, one point each); \param surface
  /// the sheet's shape, for where the disc's centre (its chart point) is in 3D (flat by default).
  DiscContactIntegrator(const Mesh& mesh, double edge_mm, int levels = 3, Shape surface = {});

  double edge_mm() const { return edge_mm_; }

  /// Adds the disc's load to `out` (whose buffers are reused: no allocation once they are
  /// large enough). Derivatives only if `derivatives`.
  void integrate(const Disc& disc, DiscLoad& out, bool derivatives = false) const;

  /// The quadrature on a triangle a rim crosses: 4^levels pieces, each its centroid and the
  /// integral of φ_i φ_j over it per unit area of the parent.
  struct Piece {
    Eigen::Vector3d centroid_barycentric;
    Eigen::Matrix3d integral;  ///< ∫ φ_i φ_j over the piece / the parent's area
  };
  const std::vector<Piece>& pieces() const { return pieces_; }
  /// Calls visit(t) for every triangle t whose centroid may be within `reach_mm` of `center_mm`
  /// seen from +z (a superset: the caller tests each), without allocating.
  template <class Visit>
  void for_each_triangle_near(const Vector2& center_mm, double reach_mm, Visit&& visit) const {
    const auto cell = [&](double v, double origin, int count) {
      return std::clamp(static_cast<int>(std::floor((v - origin) / cell_mm_)), 0, count - 1);
    };
    const int x0 = cell(center_mm.x() - reach_mm, origin_mm_.x(), columns_),
              x1 = cell(center_mm.x() + reach_mm, origin_mm_.x(), columns_);
    const int y0 = cell(center_mm.y() - reach_mm, origin_mm_.y(), rows_),
              y1 = cell(center_mm.y() + reach_mm, origin_mm_.y(), rows_);
    for (int row = y0; row <= y1; ++row) {
      const auto first_cell = static_cast<std::size_t>(row) * static_cast<std::size_t>(columns_);
      for (int k = cell_start_[first_cell + static_cast<std::size_t>(x0)];
           k < cell_start_[first_cell + static_cast<std::size_t>(x1) + 1]; ++k)
        visit(static_cast<std::size_t>(cell_triangles_[static_cast<std::size_t>(k)]));
    }
  }
  const Vector3& centroid_mm(std::size_t triangle) const { return centroid_mm_[triangle]; }
  /// The farthest vertex of a triangle from its centroid, and the largest of these.
  double reach_mm(std::size_t triangle) const { return reach_mm_[triangle]; }
  double max_reach_mm() const { return max_reach_mm_; }
  const Mesh& mesh() const { return *mesh_; }
  /// The sheet's shape, whose chart names the discs' centres.
  const Shape& surface() const { return surface_; }

 private:
  void bucket_triangles();
  /// The disc's centre in 3D and its derivatives in x and y (columns).
  struct Centre {
    Vector3 point_mm;
    Eigen::Matrix<double, 3, 2> tangents;
  };
  void add_triangle(std::size_t t, const Disc& disc, const Centre& centre, DiscLoad& out, bool derivatives) const;
  const Mesh* mesh_;
  double edge_mm_;
  Shape surface_;
  std::vector<Piece> pieces_;
  std::vector<Vector3> centroid_mm_;
  std::vector<double> reach_mm_;  ///< farthest vertex from the centroid (in 3D)
  // bucket_triangles(): a grid over the centroids, cell_triangles_ listed cell by cell (row-major).
  double max_reach_mm_ = 0, cell_mm_ = 1;
  Vector2 origin_mm_;
  int columns_ = 1, rows_ = 1;
  std::vector<int> cell_start_, cell_triangles_;
};

}  // namespace emit
