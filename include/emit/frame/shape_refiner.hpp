#pragma once
/// \file shape_refiner.hpp
/// Contact shapes (docs/physics.md, "Contact shapes"): the disc fit (contact_fitter.hpp) finds how
/// many contacts a frame holds and where; each is then refitted as an ellipse (ellipse_contact.hpp)
/// of uniform conductance, all at once, by Levenberg–Marquardt (Ceres) on the same exact model
/// (frame_predictor.hpp). The ellipse carries what the frame tells of an outline beyond its
/// centre and total conductance: the elongation and orientation of its second moments.
///
/// What it does not tell (the second moment's trace, a round contact's size: outside it, a disc's
/// field is a point source's) comes from a prior a user can state: the contact's area is held at a
/// typical press's (the calibration indenter's) and reported with the prior's σ (radii from 2 to
/// 10 mm, log-uniform: ±0.55 in log r about 5 mm holds 68 % of them, ±1.1 all). Fitting it was tried: the frame pulled
/// it to the sheet's size with the mesh's own error. Force, F ∝ A^(1+1/γ) at the fitted total conductance G, inherits
/// little of the area's σ; pressure, all of it.
///
/// On a curved sheet the ellipses are the tangent plane's at their centres (ellipse_contact.hpp):
/// centres are chart points as the disc fit's, semi-axes and area mm and mm² on the surface.
#include <array>
#include <vector>

#include "emit/frame/contact_fitter.hpp"
#include "emit/frame/ellipse_contact.hpp"

namespace emit {

struct ShapeOptions {
  /// The σ of log of the equal-area radius about the typical one (the area's prior, held and
  /// reported), as an interval that covers: of radii 2–10 mm, log-uniform, ±0.55 about the
  /// calibration's 5 mm holds 68 % (1.1/ln 5), ±2σ all. Their standard deviation, ln 5/√12 = 0.46,
  /// held 58 % (a uniform's ±σ is not a Gaussian's): `emit eval --indenters` measured 1σ
  /// coverage 40 % with it, the discs of r 3 mm (0.51 from 5) just outside.
  double log_radius_std = 0.55;
  /// The prior on the elongation e = log √(a/b): zero mean, this σ. Weak: a 30 × 3 mm bar is e 1.15.
  double elongation_std = 1.5;
  /// The model's own error, relative to each reading's δV: σ_k² = σ_noise² + (ε δV_k)². The
  /// reconstruction mesh's discretisation leaves ~0.65 % RMS of a strong press's frame unexplained
  /// (a 7 mm, 20 N press on the 60 mm sheet: χ²/M 39 for the true disc, ShapeRefiner tests), and
  /// a contact's size moves the frame by less than that: without this the fit would trade the
  /// mesh's error for a sheet-sized contact.
  double model_error_fraction = 0.002;
  int max_iterations = 30;
  void validate() const;  ///< \throw InvalidInput naming the option
};

/// The area a refit holds: an equal-area radius and the σ of its log. Undeclared, the calibration
/// indenter's with ShapeOptions::log_radius_std; declared by a user who knows the indenter
/// (FrameOptions::contact_radius_mm), its radius with a small σ.
struct AreaPrior {
  double radius_mm = 0;       ///< > 0
  double log_radius_std = 0;  ///< > 0
};

struct RefinedContact {
  Ellipse ellipse;
  /// 1σ, from the covariance at the solution (the prior included), scaled up by the misfit per
  /// degree of freedom where that exceeds 1.
  double x_std_mm = 0, y_std_mm = 0;
  double log_area_std = 0;         ///< of log A, A = π e^(2ℓ)
  double log_conductance_std = 0;  ///< of log G, G = g A: the contact's total conductance
  double orientation_std_rad = 0;  ///< of θ; large where the contact is round
  double elongation_std = 0;       ///< of e
  /// The covariance of (log G, log A), for what a contact law makes of them (pressure and force).
  double log_conductance_log_area_cov = 0;
};

class ShapeRefiner {
 public:
  /// A workspace on `shared` (its sensor, mesh, Green's function, measurements, rim and noise),
  /// which must outlive it. \throw InvalidInput for a bad option.
  explicit ShapeRefiner(const FitPrecompute& shared, ShapeOptions options = {});

  /// Refits `discs` (the disc fit's contacts for δV) as ellipses of the area of a disc of
  /// `prior`'s radius (its σ the reported area's), then lets the frame choose its regions: two merged into one where
  /// that costs less χ² than a contact's six parameters are worth (BIC, 6 ln M): a bar the disc fit covered with two
  /// discs is one region. \return the contacts; valid until the next call.
  const std::vector<RefinedContact>& refine(const Vector& dV, const std::vector<Disc>& discs, const AreaPrior& prior);

  const ShapeOptions& options() const { return options_; }
  /// The ellipses' integrator: which chart points an ellipse covers (EllipseContactIntegrator::contains).
  const EllipseContactIntegrator& integrator() const { return integrator_; }
  /// The last refit's misfit [V RMS over the measurements].
  double rms_misfit_V() const { return rms_misfit_V_; }
  /// The frame the ellipses give (N×N), for tests and pictures.
  Frame predict(const std::vector<Ellipse>& ellipses);

 private:
  friend class EllipseMisfit;
  /// `round[i]`: contact i held round (p = q = 0).
  double solve(const Vector& dV, std::vector<std::array<double, 6>>& parameters, int iterations,
               const std::vector<bool>& round = {});
  void covariances(const Vector& dV, const std::vector<std::array<double, 6>>& parameters, double chi2,
                   double log_radius_std);
  const FitPrecompute& shared_;
  ShapeOptions options_;
  EllipseContactIntegrator integrator_;
  FramePredictor predictor_;
  EllipseLoad load_;
  Frame frame_;
  Vector weight_;  ///< 1/σ_k per measurement (ShapeOptions::model_error_fraction)
  std::vector<RefinedContact> result_;
  double rms_misfit_V_ = 0;
};

}  // namespace emit
