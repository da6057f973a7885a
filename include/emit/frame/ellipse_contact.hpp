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
/// Flat sheets only: on a curved one the disc model stays.
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
  /// Whether the sheet's point (x, y) [mm] is inside.
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

class EllipseContactIntegrator {
 public:
  /// Integrates on the triangles and quadrature of `discs` (its mesh, rim width and pieces), which
  /// must outlive it.
  explicit EllipseContactIntegrator(const DiscContactIntegrator& discs) : discs_(discs) {}

  /// Adds the ellipse's load to `out` (its buffers reused: no allocation once large enough).
  void integrate(const Ellipse& ellipse, EllipseLoad& out, bool derivatives = false) const;

 private:
  const DiscContactIntegrator& discs_;
};

}  // namespace emit
