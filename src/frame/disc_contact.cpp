#include "emit/frame/disc_contact.hpp"

#include <algorithm>
#include <cmath>
#include <utility>

#include "emit/core/errors.hpp"
#include "emit/sensor/surface.hpp"

namespace emit {

void DiscLoad::clear() {
  triangles.clear();
  local_S.clear();
  d_local_S.clear();
}

namespace {

/// ∫ φ_i φ_j over a sub-triangle whose corners have barycentric coordinates B (rows) in its
/// parent, per unit parent area: with μ the piece's own coordinates, ∫ μ_k μ_l = a (1 + δ_kl) / 12.
Eigen::Matrix3d piece_integral(const Eigen::Matrix3d& B, double area_fraction) {
  Eigen::Matrix3d mu = Eigen::Matrix3d::Constant(1.0 / 12);
  mu.diagonal().setConstant(2.0 / 12);
  return area_fraction * B.transpose() * mu * B;
}

/// Splits the reference triangle into 4^levels similar pieces (corner midpoints), depth first.
void split(const Eigen::Matrix3d& B, int levels, double area_fraction, std::vector<Eigen::Matrix3d>& out) {
  if (levels == 0) {
    out.push_back(B);
    return;
  }
  const Eigen::RowVector3d m01 = (B.row(0) + B.row(1)) / 2, m12 = (B.row(1) + B.row(2)) / 2,
                           m20 = (B.row(2) + B.row(0)) / 2;
  Eigen::Matrix3d child;
  child << B.row(0), m01, m20;
  split(child, levels - 1, area_fraction / 4, out);
  child << m01, B.row(1), m12;
  split(child, levels - 1, area_fraction / 4, out);
  child << m20, m12, B.row(2);
  split(child, levels - 1, area_fraction / 4, out);
  child << m01, m12, m20;
  split(child, levels - 1, area_fraction / 4, out);
}

}  // namespace

void rim_smoothstep(double xi, double& s, double& ds_dxi) {
  if (xi >= 1) {
    s = 1, ds_dxi = 0;
  } else if (xi <= -1) {
    s = 0, ds_dxi = 0;
  } else {
    const double t = (xi + 1) / 2;
    s = t * t * (3 - 2 * t);
    ds_dxi = 3 * t * (1 - t);
  }
}

Eigen::Matrix3d uniform_integral() {
  Eigen::Matrix3d m = Eigen::Matrix3d::Constant(1.0 / 12);
  m.diagonal().setConstant(2.0 / 12);
  return m;
}

DiscContactIntegrator::DiscContactIntegrator(const Mesh& mesh, double edge_mm, int levels, Shape surface)
    : mesh_(&mesh), edge_mm_(edge_mm), surface_(std::move(surface)) {
  if (!(edge_mm > 0)) throw InvalidInput("disc contact: the rim's smoothing width must be positive");
  if (levels < 0 || levels > 5) throw InvalidInput("disc contact: quadrature levels must be 0 to 5");
  std::vector<Eigen::Matrix3d> corners;
  split(Eigen::Matrix3d::Identity(), levels, 1.0, corners);
  for (const Eigen::Matrix3d& B : corners)
    pieces_.push_back({B.colwise().mean().transpose(), piece_integral(B, std::pow(0.25, levels))});
  for (Index t = 0; t < mesh.triangle_count(); ++t) {
    const Vector3 c = mesh.triangle_centroid_mm(t);
    double reach = 0;
    for (int k = 0; k < 3; ++k)
      reach = std::max(reach, (mesh.nodes_mm.row(mesh.triangles(t, k)).transpose() - c).norm());
    centroid_mm_.push_back(c);
    reach_mm_.push_back(reach);
  }
  bucket_triangles();
}

/// Triangles by the cell of a grid their centroid lies in, seen from +z (cells of the largest
/// reach, so a disc's candidates are the cells its reach-widened square covers: seen from +z
/// distances only shrink): a disc touches tens of the mesh's thousands of triangles, and
/// integrate() runs several times per fit iteration.
void DiscContactIntegrator::bucket_triangles() {
  max_reach_mm_ = *std::max_element(reach_mm_.begin(), reach_mm_.end());
  cell_mm_ = std::max(max_reach_mm_, 1e-9);
  origin_mm_ = Vector2(INFINITY, INFINITY);
  Vector2 top(-INFINITY, -INFINITY);
  for (const Vector3& c : centroid_mm_) origin_mm_ = origin_mm_.cwiseMin(c.head<2>()), top = top.cwiseMax(c.head<2>());
  columns_ = 1 + static_cast<int>((top.x() - origin_mm_.x()) / cell_mm_);
  rows_ = 1 + static_cast<int>((top.y() - origin_mm_.y()) / cell_mm_);
  cell_start_.assign(static_cast<std::size_t>(columns_) * static_cast<std::size_t>(rows_) + 1, 0);
  const auto cell_of = [&](const Vector3& c) {
    return static_cast<int>((c.y() - origin_mm_.y()) / cell_mm_) * columns_ +
           static_cast<int>((c.x() - origin_mm_.x()) / cell_mm_);
  };
  for (const Vector3& c : centroid_mm_) ++cell_start_[static_cast<std::size_t>(cell_of(c)) + 1];
  for (std::size_t i = 1; i < cell_start_.size(); ++i) cell_start_[i] += cell_start_[i - 1];
  cell_triangles_.resize(centroid_mm_.size());
  std::vector<int> filled(cell_start_.begin(), cell_start_.end() - 1);
  for (std::size_t t = 0; t < centroid_mm_.size(); ++t)
    cell_triangles_[static_cast<std::size_t>(filled[static_cast<std::size_t>(cell_of(centroid_mm_[t]))]++)] =
        static_cast<int>(t);
}

void DiscContactIntegrator::integrate(const Disc& disc, DiscLoad& out, bool derivatives) const {
  const Vector2 chart(disc.x_mm, disc.y_mm);
  const Centre centre{surface_point_mm(surface_, chart), surface_tangents(surface_, chart)};
  const Vector2 center = centre.point_mm.head<2>();  // the buckets are seen from +z
  const double r = disc.radius_mm, h = edge_mm_;
  const double reach = r + h + max_reach_mm_;  // no centroid farther than this can be touched
  for_each_triangle_near(center, reach, [&](std::size_t t) { add_triangle(t, disc, centre, out, derivatives); });
}

void DiscContactIntegrator::add_triangle(std::size_t t, const Disc& disc, const Centre& centre, DiscLoad& out,
                                         bool derivatives) const {
  const double g = disc.conductance_S_per_mm2, r = disc.radius_mm, h = edge_mm_;
  const double d = (centroid_mm_[t] - centre.point_mm).norm();
  if (d - reach_mm_[t] >= r + h) return;  // wholly outside the smoothed rim
  const auto tri = static_cast<Index>(t);
  const double area = mesh_->triangle_area_mm2(tri);
  out.triangles.push_back(tri);
  if (d + reach_mm_[t] <= r - h) {  // wholly inside: s = 1
    out.local_S.emplace_back(g * area * uniform_integral());
    if (derivatives)
      out.d_local_S.push_back({Eigen::Matrix3d::Zero(), Eigen::Matrix3d::Zero(), Eigen::Matrix3d::Zero()});
    return;
  }
  Eigen::Matrix3d corner;
  for (int k = 0; k < 3; ++k) corner.row(k) = mesh_->nodes_mm.row(mesh_->triangles(tri, k));
  Eigen::Matrix3d local = Eigen::Matrix3d::Zero();
  std::array<Eigen::Matrix3d, 3> d_local{Eigen::Matrix3d::Zero(), Eigen::Matrix3d::Zero(), Eigen::Matrix3d::Zero()};
  for (const Piece& piece : pieces_) {
    const Vector3 offset = corner.transpose() * piece.centroid_barycentric - centre.point_mm;
    const double distance = offset.norm();
    double s, ds_dxi;
    rim_smoothstep((r - distance) / h, s, ds_dxi);
    if (s == 0 && ds_dxi == 0) continue;
    local += s * piece.integral;
    if (derivatives && ds_dxi != 0) {
      // ξ = (r − |p − c|)/h with c = P(x, y): ∂ξ/∂x = (p − c)·∂P/∂x / (|p − c| h), ∂ξ/∂r = 1/h.
      const double scale = ds_dxi / h;
      const Eigen::RowVector2d along = offset.transpose() * centre.tangents / distance;
      d_local[0] += scale * along.x() * piece.integral;
      d_local[1] += scale * along.y() * piece.integral;
      d_local[2] += scale * piece.integral;
    }
  }
  out.local_S.emplace_back(g * area * local);
  if (derivatives) out.d_local_S.push_back({g * area * d_local[0], g * area * d_local[1], g * area * d_local[2]});
}

}  // namespace emit
