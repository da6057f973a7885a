#include "emit/frame/ellipse_contact.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "emit/sensor/surface.hpp"

namespace emit {

namespace {

/// S(e) = sinh(2e)/e and T(e) = S′(e)/e, by their series near e = 0 (both even in e).
void shape_functions(double e, double& S, double& T) {
  if (e < 1e-3) {
    S = 2 + 4 * e * e / 3;
    T = 8.0 / 3 + 16 * e * e / 15;
    return;
  }
  S = std::sinh(2 * e) / e;
  T = (2 * e * std::cosh(2 * e) - std::sinh(2 * e)) / (e * e * e);
}

}  // namespace

Ellipse Ellipse::round(const Disc& disc) {
  return {disc.x_mm, disc.y_mm, std::log(disc.radius_mm), 0, 0, disc.conductance_S_per_mm2};
}
double Ellipse::elongation() const { return std::hypot(p, q); }
double Ellipse::semi_major_mm() const { return std::exp(log_radius + elongation()); }
double Ellipse::semi_minor_mm() const { return std::exp(log_radius - elongation()); }
double Ellipse::orientation_rad() const { return std::atan2(q, p) / 2; }
double Ellipse::area_mm2() const { return std::numbers::pi * std::exp(2 * log_radius); }

bool Ellipse::contains(double px_mm, double py_mm) const {
  const double e = elongation();
  double S, T;
  shape_functions(e, S, T);
  const double dx = px_mm - x_mm, dy = py_mm - y_mm;
  // dᵀ e^(−2L) d with e^(−2L) = e^(−2ℓ) (cosh 2e I − S K), K = [[p, q], [q, −p]].
  const double rho_sq = std::exp(-2 * log_radius) *
                        (std::cosh(2 * e) * (dx * dx + dy * dy) - S * (p * (dx * dx - dy * dy) + 2 * q * dx * dy));
  return rho_sq <= 1;
}

void EllipseLoad::clear() {
  triangles.clear();
  local_S.clear();
  d_local_S.clear();
}

namespace {

/// The tangent frame E at chart point c: Gram–Schmidt of the chart's tangents (a file surface's by
/// the secant, ellipse_contact.hpp; a cap's taken within its rim).
Eigen::Matrix<double, 3, 2> tangent_frame(const Shape& shape, const Vector2& c) {
  Eigen::Matrix<double, 3, 2> T;
  if (shape.kind == ShapeKind::spherical_cap) {
    const double rho = c.norm();
    T = surface_tangents(shape, rho > shape.radius_mm ? Vector2(c * (shape.radius_mm / rho)) : c);
  } else {
    for (int j = 0; j < 2; ++j) {
      const Vector2 step = file_secant_mm * Vector2::Unit(j);
      T.col(j) = (surface_point_mm(shape, c + step) - surface_point_mm(shape, c - step)) / (2 * file_secant_mm);
    }
  }
  Eigen::Matrix<double, 3, 2> E;
  E.col(0) = T.col(0).normalized();
  E.col(1) = (T.col(1) - E.col(0).dot(T.col(1)) * E.col(0)).normalized();
  return E;
}

}  // namespace

EllipseContactIntegrator::EllipseContactIntegrator(const DiscContactIntegrator& discs)
    : discs_(discs), projected_(is_curved(discs.surface()) && discs.surface().kind != ShapeKind::cylinder) {
  const Shape& shape = discs.surface();
  if (is_sleeve(shape)) round_mm_ = 2 * std::numbers::pi * shape.radius_mm;
  if (projected_) return;
  const Mesh& mesh = discs.mesh();
  const auto count = static_cast<std::size_t>(mesh.triangle_count());
  chart_corner_mm_.resize(count);
  chart_centroid_mm_.resize(count);
  chart_reach_mm_.resize(count);
  const bool cylinder = shape.kind == ShapeKind::cylinder;
  for (std::size_t t = 0; t < count; ++t) {
    std::array<Vector2, 3>& corner = chart_corner_mm_[t];
    for (int k = 0; k < 3; ++k) {
      const Vector3 node = mesh.nodes_mm.row(mesh.triangles(static_cast<Index>(t), k)).transpose();
      corner[static_cast<std::size_t>(k)] = cylinder ? surface_chart_mm(shape, node) : Vector2(node.head<2>());
    }
    for (std::size_t k = 1; k < 3; ++k) corner[k] = corner[0] + chart_offset(corner[k], corner[0]);
    chart_centroid_mm_[t] = (corner[0] + corner[1] + corner[2]) / 3;
    double reach = 0;
    for (const Vector2& c : corner) reach = std::max(reach, (c - chart_centroid_mm_[t]).norm());
    chart_reach_mm_[t] = reach;
    max_chart_reach_mm_ = std::max(max_chart_reach_mm_, reach);
  }
}

Vector2 EllipseContactIntegrator::chart_offset(const Vector2& chart_mm, const Vector2& centre_mm) const {
  Vector2 d = chart_mm - centre_mm;
  if (round_mm_ > 0) d.y() -= round_mm_ * std::round(d.y() / round_mm_);
  return d;
}

EllipseContactIntegrator::Tangent EllipseContactIntegrator::tangent(const Vector2& centre, bool derivatives) const {
  Tangent f;
  if (!projected_) return f;
  const Shape& shape = discs_.surface();
  f.point_mm = surface_point_mm(shape, centre);
  f.E = tangent_frame(shape, centre);
  f.A = -f.E.transpose() * surface_tangents(shape, centre);  // ∂d/∂c₀ = −Eᵀ ∂P/∂c₀ + (∂E)ᵀ (p − P)
  if (derivatives) {
    constexpr double step_mm = 1e-3;  // central differences: E is smooth on a cap, piecewise so on a file's secant
    for (int j = 0; j < 2; ++j) {
      const Vector2 step = step_mm * Vector2::Unit(j);
      f.dE[static_cast<std::size_t>(j)] =
          (tangent_frame(shape, centre + step) - tangent_frame(shape, centre - step)) / (2 * step_mm);
    }
  }
  return f;
}

Vector2 EllipseContactIntegrator::chart_point(const Vector2& centre_mm, const Vector2& offset_mm) const {
  if (!projected_) return centre_mm + offset_mm;
  const Tangent f = tangent(centre_mm, false);
  return surface_chart_mm(discs_.surface(), f.point_mm + f.E * offset_mm);
}

bool EllipseContactIntegrator::contains(const Ellipse& ellipse, const Vector2& chart_mm) const {
  const Vector2 centre(ellipse.x_mm, ellipse.y_mm);
  Vector2 d = chart_offset(chart_mm, centre);
  if (projected_) {
    const Tangent f = tangent(centre, false);
    const Vector3 offset = surface_point_mm(discs_.surface(), chart_mm) - f.point_mm;
    if (offset.norm() >= 2 * ellipse.semi_major_mm()) return false;  // the far side (integrate())
    d = f.E.transpose() * offset;
  }
  return ellipse.contains(ellipse.x_mm + d.x(), ellipse.y_mm + d.y());
}

void EllipseContactIntegrator::integrate(const Ellipse& el, EllipseLoad& out, bool derivatives) const {
  const Mesh& mesh = discs_.mesh();
  const double h = discs_.edge_mm(), g = el.conductance_S_per_mm2;
  const double e = el.elongation();
  const double a = el.semi_major_mm(), b = el.semi_minor_mm();
  double S, T;
  shape_functions(e, S, T);
  const double scale = std::exp(-2 * el.log_radius), cosh2e = std::cosh(2 * e);
  // Q = e^(−2L) and its derivatives in p and q (in ℓ it is −2Q).
  Eigen::Matrix2d K, dK_dp, dK_dq;
  K << el.p, el.q, el.q, -el.p;
  dK_dp << 1, 0, 0, -1;
  dK_dq << 0, 1, 1, 0;
  const Eigen::Matrix2d Q = scale * (cosh2e * Eigen::Matrix2d::Identity() - S * K);
  const Eigen::Matrix2d dQ_dp = scale * (2 * S * el.p * Eigen::Matrix2d::Identity() - T * el.p * K - S * dK_dp);
  const Eigen::Matrix2d dQ_dq = scale * (2 * S * el.q * Eigen::Matrix2d::Identity() - T * el.q * K - S * dK_dq);
  const Vector2 centre(el.x_mm, el.y_mm);
  const Vector2 major(std::cos(el.orientation_rad()), std::sin(el.orientation_rad()));
  const auto& pieces = discs_.pieces();
  const Tangent f = tangent(centre, derivatives);
  // The buckets are seen from +z. Projected: a point within the chord cut (2(a + h)) of P(c₀) is
  // within that seen from +z. In the chart: a cylinder's centroids are within their chart distance
  // of the centre's point plus a facet's sagitta (under its reach).
  const double cut_mm = 2 * (a + h);
  const bool cylinder = discs_.surface().kind == ShapeKind::cylinder;
  const Vector2 seen = projected_ || cylinder ? Vector2(surface_point_mm(discs_.surface(), centre).head<2>()) : centre;
  const double search_mm = projected_ ? cut_mm + discs_.max_reach_mm()
                           : cylinder ? a + h + max_chart_reach_mm_ + discs_.max_reach_mm()
                                      : a + h + discs_.max_reach_mm();

  discs_.for_each_triangle_near(seen, search_mm, [&](std::size_t t) {
    const auto tri = static_cast<Index>(t);
    // Each corner's offset d in the tangent plane (d is linear in the point: so is a piece's).
    Eigen::Matrix<double, 3, 2> corner;
    std::array<Eigen::Matrix<double, 3, 2>, 2> corner_dE;  // (∂E/∂c₀ⱼ)ᵀ (p − P) per corner
    double reach;
    if (projected_) {
      if ((discs_.centroid_mm(t) - f.point_mm).norm() - discs_.reach_mm(t) >= cut_mm) return;  // the far side
      for (int k = 0; k < 3; ++k) {
        const Vector3 offset = mesh.nodes_mm.row(mesh.triangles(tri, k)).transpose() - f.point_mm;
        corner.row(k) = (f.E.transpose() * offset).transpose();
        if (derivatives)
          for (std::size_t j = 0; j < 2; ++j) corner_dE[j].row(k) = (f.dE[j].transpose() * offset).transpose();
      }
      reach = discs_.reach_mm(t);  // a projection moves points no farther apart
    } else {
      const Vector2 shift = chart_offset(chart_centroid_mm_[t], centre) - (chart_centroid_mm_[t] - centre);
      for (std::size_t k = 0; k < 3; ++k) corner.row(static_cast<Index>(k)) = chart_corner_mm_[t][k] + shift - centre;
      reach = chart_reach_mm_[t];
    }
    const Vector2 offset = corner.colwise().mean().transpose();
    const double distance = offset.norm();
    if (distance - reach >= a + h) return;  // wholly outside the smoothed rim: R(φ) ≤ a
    // Or outside the rim's bounding box along the axes (a long thin ellipse's disc of radius a
    // holds far more triangles than the ellipse).
    const double along = offset.dot(major), across = offset.x() * major.y() - offset.y() * major.x();
    if (std::abs(along) - reach >= a + h || std::abs(across) - reach >= b + h) return;
    const double area = mesh.triangle_area_mm2(tri);
    if (distance + reach <= b - h) {  // wholly inside: R(φ) ≥ b
      out.triangles.push_back(tri);
      out.local_S.emplace_back(g * area * uniform_integral());
      if (derivatives) out.d_local_S.emplace_back().fill(Eigen::Matrix3d::Zero());
      return;
    }
    Eigen::Matrix3d local = Eigen::Matrix3d::Zero();
    std::array<Eigen::Matrix3d, EllipseLoad::shape_parameters> d_local;
    d_local.fill(Eigen::Matrix3d::Zero());
    bool touched = false;  // some piece within the rim's smoothing
    for (const DiscContactIntegrator::Piece& piece : pieces) {
      const Vector2 d = corner.transpose() * piece.centroid_barycentric;
      const double length = d.norm();
      if (length < 1e-12) {  // the centre: R(φ) ≥ b, inside unless the ellipse is thinner than its rim
        local += piece.integral;
        continue;
      }
      const Vector2 Qd = Q * d;
      const double rho = std::sqrt(d.dot(Qd));
      double s, ds_dxi;
      rim_smoothstep(length * (1 / rho - 1) / h, s, ds_dxi);  // ξ = (R(φ) − |d|)/h, R(φ) = |d|/ρ
      if (s == 0 && ds_dxi == 0) continue;
      touched = true;
      local += s * piece.integral;
      if (!derivatives || ds_dxi == 0) continue;
      // ∂ξ/∂d = ((1/ρ − 1) d/|d| − |d| Q d/ρ³)/h, through ∂d/∂c₀ = A + (∂E/∂c₀)ᵀ (p − P(c₀));
      // ∂ξ/∂ℓ = |d|/(ρ h); ∂ξ/∂(p, q) = −|d| dᵀ (∂Q) d / (2 ρ³ h).
      const Vector2 dxi_dd = ((1 / rho - 1) * d / length - length * Qd / (rho * rho * rho)) / h;
      Vector2 d_centre = f.A.transpose() * dxi_dd;
      if (projected_)
        for (std::size_t j = 0; j < 2; ++j)
          d_centre[static_cast<Index>(j)] += dxi_dd.dot(corner_dE[j].transpose() * piece.centroid_barycentric);
      const double factor = ds_dxi;
      d_local[0] += factor * d_centre.x() * piece.integral;
      d_local[1] += factor * d_centre.y() * piece.integral;
      d_local[2] += factor * length / (rho * h) * piece.integral;
      const double shape = -length / (2 * rho * rho * rho * h);
      d_local[3] += factor * shape * d.dot(dQ_dp * d) * piece.integral;
      d_local[4] += factor * shape * d.dot(dQ_dq * d) * piece.integral;
    }
    if (local.isZero(0) && !touched) return;  // within the box, not the rim
    out.triangles.push_back(tri);
    out.local_S.emplace_back(g * area * local);
    if (derivatives) {
      auto& dl = out.d_local_S.emplace_back();
      for (int j = 0; j < EllipseLoad::shape_parameters; ++j)
        dl[static_cast<std::size_t>(j)] = g * area * d_local[static_cast<std::size_t>(j)];
    }
  });
}

}  // namespace emit
