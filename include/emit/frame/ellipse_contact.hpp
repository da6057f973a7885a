#pragma once
/// \file ellipse_contact.hpp
/// A contact's shape beyond the held disc (docs/physics.md, "Contact shapes"): an ellipse of
/// uniform contact conductance g per area, the disc model's generalisation to the outlines a
/// frame can tell apart. Outside a contact its field is a point source's plus, first, its
/// quadrupole, the outline's second moments: a frame pins a contact's centre, its total
/// conductance and the elongation and orientation of its outline; an ellipse has exactly those.
///
/// Parameters (smooth everywhere, also through the round shape where an angle is undefined):
/// the centre (x, y) and the matrix logarithm of the shape, L = ℓ I + [[p, q], [q, −p]]. With
/// e = √(p² + q²) the semi-axes are a = e^(ℓ+e) and b = e^(ℓ−e), the major axis at
/// θ = atan2(q, p)/2 from +x; a point d from the centre is inside when dᵀ e^(−2L) d ≤ 1.
/// e^(ℓ) is the radius of the disc of the same area.
///
/// As for the disc, the rim is smoothed (a C¹ smoothstep of ξ = (R(φ) − |d|)/edge, R(φ) the
/// ellipse's radius in the point's direction) so the frame is smooth in the parameters.
///
/// On a curved sheet (sensor/surface.hpp) the centre is a chart point c₀, as a disc's, and the
/// ellipse lives in the sheet's tangent plane there, d in mm in an orthonormal frame (e₁, e₂) of it
/// whose e₁ is the chart's first direction (+x on a cap and a file's surface, along the axis on a
/// cylinder); orientation is from e₁.
///   - On a cylinder, whose chart is an isometry, d is the chart's offset c − c₀ (the short way
///     round a sleeve): exact, the ellipse drawn on the unrolled sheet.
///   - On a cap and a file's surface, d = Eᵀ (p − P(c₀)), the projection of a point p of the sheet
///     onto the tangent plane at the centre's point P(c₀). A round ellipse is then the part of
///     the surface within a cylinder of radius r about the normal: on a sphere it is symmetric
///     about the centre as the disc's ball is (the frozen metric of the chart was tried: its
///     lopsided outline moved the twin's dome presses' centres by 0.27 mm against the fit's 0.05),
///     and of area πr² (1 + r²/4R² + …) on the surface (1 % more at r 5 mm on the 25 mm dome). Only points whose
///     chord from P(c₀) is under twice the reach are taken: the far side of a fingertip projects
///     near the centre too. A file's surface has piecewise constant tangents (its triangles'): its
///     E is the secant's over ±file_secant_mm, so that it is continuous in c₀.
#include <array>
#include <vector>

#include <Eigen/Core>

#include "emit/frame/disc_contact.hpp"

namespace emit {

struct Ellipse {
  double x_mm = 0, y_mm = 0;
  double log_radius = 0;  ///< ℓ: log of the equal-area disc's radius [log mm]
  double p = 0, q = 0;    ///< the shape's elongation: e = √(p² + q²) = log √(a/b), at 2θ
  double conductance_S_per_mm2 = 0;

  /// A round one: the disc.
  static Ellipse round(const Disc& disc);
  double elongation() const;       ///< e
  double semi_major_mm() const;    ///< a = e^(ℓ+e)
  double semi_minor_mm() const;    ///< b = e^(ℓ−e)
  double orientation_rad() const;  ///< θ of the major axis from +x, in (−π/2, π/2]
  double area_mm2() const;         ///< π a b = π e^(2ℓ)
  /// Whether the flat sheet's point (x, y) [mm] is inside (on a curved sheet:
  /// EllipseContactIntegrator::contains).
  bool contains(double x_mm, double y_mm) const;
};

/// An ellipse's contact load: touched triangles, their 3×3 matrices [S], and, if asked, their
/// derivatives in x, y, ℓ, p and q.
struct EllipseLoad {
  static constexpr int shape_parameters = 5;
  std::vector<Index> triangles;
  std::vector<Eigen::Matrix3d> local_S;
  std::vector<std::array<Eigen::Matrix3d, shape_parameters>> d_local_S;
  void clear();
};

/// The half-width of the secant that gives a file surface's tangent frame (above) [mm].
inline constexpr double file_secant_mm = 1.0;

class EllipseContactIntegrator {
 public:
  /// Integrates on the triangles and quadrature of `discs` (its mesh, rim width, pieces and
  /// surface), which must outlive it.
  explicit EllipseContactIntegrator(const DiscContactIntegrator& discs);

  /// Adds the ellipse's load to `out` (its buffers reused: no allocation once large enough).
  void integrate(const Ellipse& ellipse, EllipseLoad& out, bool derivatives = false) const;

  /// Whether the sheet's point of chart c is inside the ellipse, measured as integrate() does.
  bool contains(const Ellipse& ellipse, const Vector2& chart_mm) const;
  /// The chart point at tangent-plane offset d [mm] from the centre c₀ (above): c₀ + d on a flat
  /// sheet and a cylinder; on a cap and a file's surface the chart point of P(c₀) + E d, a point
  /// of the tangent plane (its outline's points, to second order in |d|/R of the surface's).
  Vector2 chart_point(const Vector2& centre_mm, const Vector2& offset_mm) const;
  /// The offset c − c₀ of chart points, the short way round a sleeve.
  Vector2 chart_offset(const Vector2& chart_mm, const Vector2& centre_mm) const;

 private:
  /// The tangent plane at the centre: P(c₀), E (3×2), A = ∂d/∂c₀ at p = P(c₀) (−EᵀT; −I in
  /// the chart) and, if asked, E's derivatives in c₀.
  struct Tangent {
    Vector3 point_mm = Vector3::Zero();
    Eigen::Matrix<double, 3, 2> E = Eigen::Matrix<double, 3, 2>::Identity();
    Eigen::Matrix2d A = -Eigen::Matrix2d::Identity();
    std::array<Eigen::Matrix<double, 3, 2>, 2> dE{};
  };
  Tangent tangent(const Vector2& centre_mm, bool derivatives) const;

  const DiscContactIntegrator& discs_;
  bool projected_ = false;  ///< a cap or a file's surface: d by projection, else the chart's offset
  double round_mm_ = 0;     ///< a sleeve's circumference (its chart's period in v), else 0
  /// Each triangle's corners' chart points (around a sleeve, the nearest images of the first),
  /// their mean, and the farthest corner from it (unused where projected_).
  std::vector<std::array<Vector2, 3>> chart_corner_mm_;
  std::vector<Vector2> chart_centroid_mm_;
  std::vector<double> chart_reach_mm_;
  double max_chart_reach_mm_ = 0;
};

}  // namespace emit
