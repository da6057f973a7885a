#pragma once
/// \file press_response.hpp
/// A skin's response to a press, learned from presses of known place (touch localisation on
/// real skins; docs/physics.md, "Touch localisation from calibration presses").
/// A frame of a current-injection skin is M readings; a press changes them from the unpressed
/// reference taken just before it. Its relative change, normalised,
///   d = log(V / V_ref) / ‖log(V / V_ref)‖,
/// is modelled as a smooth function of the press's centre p plus noise:
///   d(p) ≈ Wᵀ b(p),   b(p) = the monomials of (p − c)/s up to `degree` (degree 2: 1, u, v, u², uv, v²),
/// then, for a kernel response, Gaussian bumps exp(−‖p − c_j‖² / 2ℓ²) about centres c_j on a
/// hexagonal lattice of spacing ℓ (a smooth response over the skin, as a Gaussian process's mean
/// with the bumps' ridge as its prior: calibrate/press_response_fit.hpp),
/// with the noise's precision Λ (the inverse of the residual covariance, shrunk towards its
/// diagonal). The press is then located by maximum likelihood with a free amplitude a ≥ 0:
/// min over (p, a) of (d − a m(p))ᵀ Λ (d − a m(p)), m(p) = Wᵀ b(p), i.e. max (dᵀΛm)² / (mᵀΛm)
/// over dᵀΛm > 0 (frame/press_locator.hpp). The model needs no geometry: the electrodes' places,
/// the skin's scale and its contact impedances are all in W, which is why a skin whose geometry is
/// only roughly known is calibrated as well as one drawn exactly.
///
/// Fitted by calibrate/press_response_fit.hpp; this file holds the model and its evaluation.
#include <vector>

#include "emit/core/types.hpp"
#include "emit/model/reading_screen.hpp"

namespace emit {

struct PressResponse {
  int degree = 0;                   ///< of the monomials in b(p)
  std::vector<Vector2> centres_mm;  ///< the kernel's bumps' centres (empty: monomials alone)
  double kernel_length_mm = 0;      ///< ℓ, their width
  Vector2 center_mm{0, 0};          ///< c: the calibration presses' centre
  double scale_mm = 1;              ///< s: their largest distance from c, so |u|, |v| ≤ 1 where they were
  /// Where presses are looked for: the calibration presses' convex hull, counter-clockwise (a
  /// polynomial is trusted where it was fitted, not beyond).
  std::vector<Vector2> region_mm;
  Matrix coefficients;  ///< W, basis_size(degree) × M
  Matrix precision;     ///< Λ, M × M, symmetric positive definite
  /// k and u₀: a located press's position σ is k √(1 − explained + u₀) (frame/press_locator.hpp,
  /// "How sure"); set when fitted, on presses the fit did not see; k = 0: no σ.
  double error_scale_mm = 0, unexplained_floor = 0;

  Index readings() const { return coefficients.cols(); }
  /// B, the number of basis functions: the monomials' and the bumps'.
  Index basis_size() const;
  /// b(p) into `basis` (basis_size() entries). Allocates nothing.
  void basis_at(const Vector2& p_mm, Eigen::Ref<Vector> basis) const;
  /// Whether p is in the region (on its border counts). Allocates nothing.
  bool in_region(const Vector2& p_mm) const;
};

/// The convex hull of points, counter-clockwise, without collinear points (Andrew's monotone
/// chain); fewer than 3 distinct points give what there is.
std::vector<Vector2> convex_hull(std::vector<Vector2> points);

/// The number of monomials in two variables up to `degree`: (degree + 1)(degree + 2)/2.
Index response_basis_size(int degree);

/// A hexagonal lattice of spacing `spacing_mm` (one point at `centre_mm`), the points within
/// `radius_mm` of it: the kernel's centres.
std::vector<Vector2> hexagonal_lattice(const Vector2& centre_mm, double radius_mm, double spacing_mm);

/// The normalised relative change d of a frame against its reference into `change` (M entries):
/// log(V / V_ref) where the screen can use the reading and its reference, NaN where it cannot (a
/// masked reading), 0 on a channel the screen drops; normalised over the readings used.
/// Allocates nothing. \return ‖log(V / V_ref)‖ over the readings used, the size of the change
/// before normalising; 0, leaving `change` unspecified, when no reading can be used or the frame
/// equals its reference (no change to normalise).
double relative_change(const Eigen::Ref<const Vector>& frame, const Eigen::Ref<const Vector>& reference,
                       Eigen::Ref<Vector> change, const ReadingScreen& screen = {});

}  // namespace emit
