#pragma once
/// \file resolvability.hpp
/// What a frame can tell (docs/physics.md, "What a frame can tell"), from the exact forward model
/// contact fitting uses (frame/frame_predictor.hpp on the fit mesh and its Green's function) and
/// the readings' noise (sensor/adc.hpp), with no reconstruction in the way:
///  - the Cramér–Rao bound on a round contact's centre, radius and force: the Fisher information
///    F = JᵀJ/σ² of the frame's derivative J in (x, y, r, log g) (the fitter's disc,
///    frame/disc_contact.hpp), each parameter's σ the root of F⁻¹'s diagonal;
///  - whether two parallel bars are told from one region: the frame of the two against that of the
///    best-fitting single bar (its width, length and conductance fitted), Δχ² = min ‖Δ‖²/σ²;
///  - whether a ring's hole is seen: a ring's frame against the best-fitting full disc (radius and
///    conductance fitted).
/// Δχ² is the noncentrality of the likelihood-ratio test between the two: with Δχ² ≥ 16 one frame
/// tells them apart with under 2.3 % error either way (Φ(−√Δχ²/2)); n frames averaged multiply it
/// by n. Regions other than the disc are uniform conductance inside an outline whose rim is
/// smoothed over ±rim_mm (a C¹ step of the signed distance), so that the fits are smooth.
/// Flat sheets only.
#include <functional>
#include <string>
#include <vector>

#include <Eigen/Dense>

#include "emit/frame/disc_contact.hpp"
#include "emit/frame/frame_predictor.hpp"
#include "emit/model/fit_model.hpp"
#include "emit/model/measurements.hpp"
#include "emit/sensor/sensor.hpp"

namespace emit {

/// \throw InvalidInput "<what>: a flat sheet only (…)" unless the sheet is flat (a rectangle,
/// circle or polygon).
void require_flat_sheet(const Sensor& sensor, const std::string& what);

/// 1σ Cramér–Rao bounds for one round flat press (a disc of uniform conductance).
struct RoundContactBound {
  double x_std_mm = 0, y_std_mm = 0, radius_std_mm = 0;
  double log_conductance_std = 0;  ///< of g [S/mm²]
  double log_total_std = 0;        ///< of g·πr², what the frame pins
  double log_force_std = 0;        ///< of F = P(g)·πr² through the contact law (eq. 2)
  double signal_rms_V = 0;         ///< the press's δV, RMS over the measurements
};

/// A region of uniform conductance: its signed distance [mm] (< 0 inside), 1-Lipschitz.
using SignedDistance = std::function<double(const Vector2&)>;

/// The best single-region explanation of a frame, and how far the frame is from it.
struct AlternativeFit {
  double delta_chi2 = 0;           ///< min ‖frame − alternative‖² / σ²
  std::vector<double> parameters;  ///< the fitted shape's (mm) and log g last
  double signal_chi2 = 0;          ///< ‖frame's δV‖² / σ², for scale
};

class Resolvability {
 public:
  /// Δχ² at which one frame tells two hypotheses apart (2.3 % error either way).
  static constexpr double resolved_delta_chi2 = 16;

  /// Keeps references to all three, which must outlive it. `reference_frames`: the no-contact
  /// reference averages this many (its noise adds to δV's: model/image_noise.hpp).
  /// \throw InvalidInput for a curved sheet or a bad count.
  Resolvability(const Sensor& sensor, const FitModel& fit, const MeasurementSet& measurements,
                int reference_frames = 10);

  double noise_V() const { return noise_V_; }

  /// The bound for a flat press of `radius_mm` and `force_N` at `centre_mm`.
  RoundContactBound round_contact_bound(const Vector2& centre_mm, double radius_mm, double force_N);

  /// Its frame's derivative over the measurements, in units of the noise (M × 4: x, y, r [per
  /// mm], log g), and the frame's own δV in `dV` if given.
  Eigen::Matrix<double, Eigen::Dynamic, 4> round_contact_jacobian(const Vector2& centre_mm, double radius_mm,
                                                                  double force_N, Vector* dV = nullptr);

  /// Two parallel bars `width_mm` × `length_mm` (long along y), `gap_mm` apart across x, centred
  /// at `centre_mm`, each at `pressure`: against the best single bar about the same centre.
  /// `hold_pressure`: the single bar at the bars' own pressure (a prior that knows it), only its
  /// shape fitted.
  AlternativeFit two_bars_against_one(const Vector2& centre_mm, double width_mm, double length_mm, double gap_mm,
                                      double pressure_N_per_mm2, bool hold_pressure = false);

  /// A ring of radii `inner_mm` < `outer_mm` at `pressure`: against the best full disc about its centre.
  /// `hold_pressure`: the disc at the ring's pressure, only its radius fitted.
  AlternativeFit ring_against_disc(const Vector2& centre_mm, double inner_mm, double outer_mm,
                                   double pressure_N_per_mm2, bool hold_pressure = false);

  /// The measurements' δV of a region (with no region for reference), for tests.
  Vector region_dV(const SignedDistance& region, double conductance_S_per_mm2);

  double rim_mm = 0.5;  ///< the outlines' smoothed rim, half-width

 private:
  /// Levenberg–Marquardt on `parameters` (central differences, `steps`) of the frame `shape`
  /// gives, against `target` δV; the last (log g) held if `hold_last`.
  AlternativeFit fit_alternative(const Vector& target,
                                 const std::function<SignedDistance(const Eigen::VectorXd&)>& shape,
                                 Eigen::VectorXd parameters, const Eigen::VectorXd& steps, bool hold_last);
  const Sensor& sensor_;
  const FitModel& fit_;
  const MeasurementSet& measurements_;
  double noise_V_ = 0;
  FramePredictor predictor_;
  DiscContactIntegrator integrator_;
  Frame frame_, d_frame_;
  std::vector<Eigen::Matrix3d> piece_integrals_;    ///< per piece, ∫φ_iφ_j / the parent's area
  std::vector<Eigen::Vector3d> piece_barycentric_;  ///< per piece, its centroid
};

}  // namespace emit
