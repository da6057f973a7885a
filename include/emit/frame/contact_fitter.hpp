#pragma once
/// \file contact_fitter.hpp
/// Model-based contact fitting (docs/physics.md, "Contact fitting"; beyond the paper): each contact a disc (centre,
/// radius, contact conductance, disc_contact.hpp); the frame it gives predicted on the
/// reconstruction mesh (frame_predictor.hpp); the discs fitted to the measured δV by
/// Levenberg–Marquardt (Ceres). The linear image only seeds it. The linear method's error is
/// model bias; fitting the physics removes it.
///
/// Multi-touch: start from the strongest seed; add a contact, seeded at the next seed or at the
/// peak of the residual's linear image, while doing so cuts the misfit by a clear fraction.
#include <array>
#include <functional>
#include <memory>
#include <vector>

#include <Eigen/Geometry>

#include "emit/fem/forward_model.hpp"
#include "emit/frame/disc_contact.hpp"
#include "emit/frame/frame_predictor.hpp"
#include "emit/model/measurements.hpp"
#include "emit/sensor/sensor.hpp"

namespace emit {

struct FitOptions {
  int max_contacts = 4;  ///< fingers at once (a hand's: `emit eval --realistic` measures three and four)
  double edge_mm = 0;    ///< the disc's rim smoothing half-width; 0: a quarter of the mesh size
  /// The model disc's radius, held. While the contact's resistance dwarfs the sheet's spreading
  /// resistance (the current-source regime, docs/physics.md, "Contact fitting"), a disc's field
  /// outside it is a point source's (the mean-value property): the frame pins the centre and
  /// g·area sharply and the radius hardly at all. So the radius is held small: the centre does not
  /// depend on it, a small disc never reaches over the border (a 4 mm disc there biased the centre
  /// by up to 0.9 mm on the 30 mm sheet; 2 mm: 0.06 mm), and its patch, and so each prediction,
  /// stays small (2 frames/s → 33 frames/s there). A fitted radius (with a log-normal prior) was
  /// tried and dropped: on the twin it wandered to its bounds without moving the centre. Pressure
  /// comes from g·area through a calibration (contacts of one indenter), not from the radius.
  double prior_radius_mm = 0;  ///< 0: twice the mesh's element size
  void validate() const;       ///< \throw InvalidInput naming the option
};

/// The options with each 0 ("default") filled in for the sensor and the fit mesh.
/// \throw InvalidInput as FitOptions::validate, or if the sheet is under two elements across.
FitOptions resolved_fit_options(FitOptions options, const Sensor& sensor, const Mesh& mesh);

struct FittedContact {
  Disc disc;
  double x_std_mm = 0, y_std_mm = 0;  ///< 1σ from the fit's covariance
  double radius_std_mm = 0;
  double conductance_relative_std = 0;
  double pressure_N_per_mm2 = 0;      ///< from g by the sensor's contact law (paper eq. 2)
  double pressure_std_N_per_mm2 = 0;  ///< P ∝ g^(−1/γ): σ_P = P σ_log g / |γ|
};

struct FitResult {
  std::vector<FittedContact> contacts;  ///< strongest (largest g·area) first
  double rms_misfit_V = 0;              ///< RMS of predicted − measured over the measurements
  int evaluations = 0;                  ///< frames predicted
  bool tracked = false;                 ///< started from the last frame's contacts (ContactFitter::track)
};

/// The fitter's immutable part, built once per sensor, fit mesh and Green's function: the options
/// resolved, the disc integrator, and the atoms (a held disc's frame on a grid over the sheet) with
/// their Gram matrix. Read-only once built, it is shared by any number of ContactFitters on any
/// threads (Pipeline holds one; each Reconstructor fits with its own ContactFitter on it).
class FitPrecompute {
 public:
  /// Keeps references to all but `options`; they must outlive it. \throw InvalidInput.
  FitPrecompute(const Sensor& sensor, const Mesh& mesh, const DenseGreenFunction& green,
                const MeasurementSet& measurements, FitOptions options = {});
  FitPrecompute(const FitPrecompute&) = delete;  // fitters refer to it
  FitPrecompute& operator=(const FitPrecompute&) = delete;
  ~FitPrecompute() = default;

  const Sensor& sensor() const { return sensor_; }
  const Mesh& mesh() const { return mesh_; }
  const DenseGreenFunction& green() const { return green_; }
  const MeasurementSet& measurements() const { return measurements_; }
  const FitOptions& options() const { return options_; }
  double noise_V() const { return noise_V_; }
  const DiscContactIntegrator& integrator() const { return integrator_; }
  /// Where contacts' centres may go (mesh/sheet_chart.hpp).
  const Eigen::AlignedBox2d& centre_box() const { return chart_box_; }

 private:
  friend class ContactFitter;
  friend class FrameMisfit;
  void build_atoms();
  bool best_atom_set(const Vector& target, int count, std::vector<Disc>& set) const;
  Disc clamp_seed(Disc seed) const;
  bool plausible_set(const std::vector<Disc>& discs) const;
  bool explained(double misfit_sq, const Vector& dV) const;
  bool jumped(const std::vector<Disc>& previous, const std::vector<Disc>& discs) const;
  double separation_mm(const Disc& a, const Disc& b) const;
  /// Two contacts closer than this are one press (three held radii).
  double plausible_separation_mm() const { return 3 * options_.prior_radius_mm; }

  const Sensor& sensor_;
  const Mesh& mesh_;
  const DenseGreenFunction& green_;
  const MeasurementSet& measurements_;
  Eigen::AlignedBox2d chart_box_;  ///< where the discs' centres may go (mesh/sheet_chart.hpp)
  FitOptions options_;
  DiscContactIntegrator integrator_;
  double noise_V_;
  Matrix atoms_, atom_gram_;  ///< build_atoms()
  std::vector<Disc> atom_discs_;
};

/// Fits contacts to frames: the per-thread half (its predictor's scratch, the load, the result)
/// on a shared FitPrecompute. One ContactFitter serves one thread at a time; several, on one
/// precompute, fit at once with no lock, each giving what it would give alone.
class ContactFitter {
 public:
  /// A further contact is kept only if it cuts the misfit (sum of squares) by this fraction.
  static constexpr double new_contact_gain = 0.5;
  /// When the contacts explain a frame, so that no further contact is tried (and tracking holds):
  /// while the misfit is within the readings' noise, or while what it has beyond the noise is
  /// model error, small against the frame itself. A fixed multiple of the noise cannot tell them
  /// apart: one disc leaves a strong single press on the 60 mm sheet up to χ²/M ≈ 13 (its shape,
  /// not a held disc's), and two presses 6–10 mm apart on the 30 mm sheet as little as 2.4.
  /// Relative to the frame they part: over 5 seeds of the twin, singles at up to 0.5 N/mm² left
  /// at most 2.5e-3 of the frame's RMS beyond the noise, every pair at least 3.5e-3.
  static constexpr double noise_chi2_per_measurement =
      2;  ///< the noise alone: χ²/M = 1 ± 0.09 (M = 240); 2 is 11 of its σ beyond
  static constexpr double model_error_rms_fraction = 3e-3;  ///< between the two above
  static constexpr int max_iterations = 50;                 ///< of one Levenberg–Marquardt run

  /// A workspace on `shared`, which must outlive it.
  explicit ContactFitter(const FitPrecompute& shared);
  /// A fitter with a precompute of its own (one fitter, one thread: tests, calibrations).
  /// Keeps references to all but `options`; they must outlive it. \throw InvalidInput.
  ContactFitter(const Sensor& sensor, const Mesh& mesh, const DenseGreenFunction& green,
                const MeasurementSet& measurements, FitOptions options = {});

  /// Fits contacts to δV (one value per measurement), seeded by `seeds` (strongest first; their
  /// conductance may be 0: a default is used). `residual_peak` is called with the current misfit
  /// (per measurement) to propose a seed for one more contact; it may be empty.
  const FitResult& fit(const Vector& dV, const std::vector<Disc>& seeds,
                       const std::function<bool(const Vector& misfit, Disc& seed)>& residual_peak = {});

  /// Tracking: refits the previous frame's contacts from where they were, in one
  /// Levenberg–Marquardt run without seeds. The result is empty, not `tracked`, if that does
  /// not explain the frame as fit() would accept (a misfit beyond the noise and the model's error,
  /// FitOptions: a new touch), moves one of several discs further than two presses' plausible
  /// separation (pulled elsewhere, or into a local minimum), leaves a contact the readings cannot
  /// see (5σ: a lifted finger), or an implausible set (two beside each other, or one off the
  /// sheet); then call fit().
  const FitResult& track(const Vector& dV, const std::vector<Disc>& previous);

  /// The frame the discs give (N×N), for tests and pictures.
  Frame predict(const std::vector<Disc>& discs);
  double noise_V() const { return shared_.noise_V_; }
  const FitPrecompute& shared() const { return shared_; }

 private:
  friend class FrameMisfit;
  friend class FitPrecompute;  // build_atoms predicts with a fitter of its own
  double fit_discs(const Vector& dV, std::vector<Disc>& discs);
  void misfit(const std::vector<Disc>& discs, const Vector& dV, Vector& out);
  void finish(const Vector& dV, const std::vector<Disc>& discs, double misfit_sq);
  void add_starts(const std::vector<Disc>& discs, const Disc& seed, std::vector<std::vector<Disc>>& starts) const;
  bool fit_best_start(const Vector& dV, std::vector<std::vector<Disc>>& starts, std::vector<Disc>& best,
                      double& best_sq);
  void parameter_std(const Vector& dV, std::vector<std::array<double, 4>>& parameters, double chi2);

  std::unique_ptr<const FitPrecompute> owned_;  ///< the convenience constructor's
  const FitPrecompute& shared_;
  FramePredictor predictor_;
  DiscLoad load_;
  Frame frame_;
  FitResult result_;
  std::vector<double> covariance_std_;
  Vector residual_, zeros_;
};

}  // namespace emit
