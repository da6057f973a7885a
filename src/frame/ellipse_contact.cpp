#include "emit/frame/ellipse_contact.hpp"

#include <cmath>
#include <numbers>

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

  discs_.for_each_triangle_near(centre, a + h + discs_.max_reach_mm(), [&](std::size_t t) {
    const double distance = (discs_.centroid_mm(t).head<2>() - centre).norm();
    const double reach = discs_.reach_mm(t);
    if (distance - reach >= a + h) return;  // wholly outside the smoothed rim: R(φ) ≤ a
    // Or outside the rim's bounding box along the axes (a long thin ellipse's disc of radius a
    // holds far more triangles than the ellipse).
    const Vector2 offset = discs_.centroid_mm(t).head<2>() - centre;
    const double along = offset.dot(major), across = offset.x() * major.y() - offset.y() * major.x();
    if (std::abs(along) - reach >= a + h || std::abs(across) - reach >= b + h) return;
    const auto tri = static_cast<Index>(t);
    const double area = mesh.triangle_area_mm2(tri);
    if (distance + reach <= b - h) {  // wholly inside: R(φ) ≥ b
      out.triangles.push_back(tri);
      out.local_S.emplace_back(g * area * uniform_integral());
      if (derivatives) out.d_local_S.emplace_back().fill(Eigen::Matrix3d::Zero());
      return;
    }
    Eigen::Matrix3d corner;
    for (int k = 0; k < 3; ++k) corner.row(k) = mesh.nodes_mm.row(mesh.triangles(tri, k));
    Eigen::Matrix3d local = Eigen::Matrix3d::Zero();
    std::array<Eigen::Matrix3d, EllipseLoad::shape_parameters> d_local;
    d_local.fill(Eigen::Matrix3d::Zero());
    bool touched = false;  // some piece within the rim's smoothing
    for (const DiscContactIntegrator::Piece& piece : pieces) {
      const Vector2 d = (corner.transpose() * piece.centroid_barycentric).head<2>() - centre;
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
      // ∂ξ/∂c = (−(1/ρ − 1) d/|d| + |d| Q d/ρ³)/h; ∂ξ/∂ℓ = |d|/(ρ h);
      // ∂ξ/∂(p, q) = −|d| dᵀ (∂Q) d / (2 ρ³ h).
      const Vector2 d_centre = (-(1 / rho - 1) * d / length + length * Qd / (rho * rho * rho)) / h;
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
