#pragma once
/// \file sensor_calibration.hpp
/// Self-calibration of the sheet from presses at known places (a real sheet is not its
/// description). Contact fitting reads a contact's position from the shape of the frame, which the
/// sheet shapes too. Given presses whose centres are known (the calibration presses of `emit
/// calibrate`), it fits, to all their frames at once by Levenberg–Marquardt (Ceres):
///
/// - the sheet's resistance field, a smooth correction (sheet_correction.hpp, cubic: 9 terms);
/// - each electrode's place along the border (mesh/slide_electrodes.hpp: the mesh slides, its
///   topology kept, so the frames are smooth in the shifts);
/// - each electrode's series resistance R_l (its contact plus the switch: the grounded electrode
///   reaches ground through it, frame_predictor.hpp);
/// - the drive voltage E;
///
/// each press a disc held at its true centre with its own contact conductance, solved for inside
/// each evaluation (variable projection: the outer problem has the sheet's, the electrodes' and
/// the drive's parameters only). Weak priors (the plausible range of a real sheet) keep a
/// parameter the presses cannot see at its nominal value; identifiability is read from the fit's
/// Jacobian: a parameter is *determined* when the presses shrink its statistical uncertainty
/// below half its prior's (the posterior 1σ from (JᵀJ + prior)⁻¹, scaled by the misfit per
/// reading when the model misfits beyond the noise). The reported σ adds the model's own error in
/// quadrature (a floor per kind of parameter, measured over realistic sheets: docs/physics.md,
/// "How sure"), so that it covers the truth of a real sheet, not only the noise.
///
/// What presses cannot tell, by the physics (docs/physics.md, "Self-calibration"):
/// - the sheet's overall resistance: scaling σ by s is the same as scaling every contact
///   conductance by 1/s and every series resistance by s, so only R·σ is seen (R is reported as
///   the nominal sheet sees it, which is what the reconstruction needs);
/// - a radially symmetric spread of a contact (an elastomer cover's blur, the indenter's profile):
///   while the contact is a current source its field outside it is a point source's (the
///   mean-value property); the contact law, calibrated with the same indenter, absorbs it.
#include <functional>
#include <string>
#include <vector>

#include "emit/frame/contact_fitter.hpp"
#include "emit/model/sheet_correction.hpp"
#include "emit/sensor/press.hpp"

namespace emit {

/// One fitted parameter with its uncertainty.
/// The fewest presses calibrate_sensor takes. Eight place a press as well as forty on the
/// realistic 60 mm sheet (README, "A realistic sheet"): the presses fit a few dozen parameters of
/// the physics, not a response per place.
constexpr int least_calibration_presses = 8;

struct CalibratedParameter {
  std::string name;  ///< "sheet θ_u", "drive_voltage_V", "series_resistance_ohm[3]"
  double value = 0;  ///< in the unit its name says
  double std = 0;    ///< 1σ: the posterior's and the model's error in quadrature
  double prior_std = 0;
  bool determined = false;  ///< the posterior's σ < half of prior_std: the presses, not the prior, set it
};

struct SensorCalibrationOptions {
  int sheet_terms = SheetCorrection::cubic_terms;  ///< 5 (quadratic) or 9 (cubic)
  bool fit_series_resistance = true;
  bool fit_drive_voltage = true;
  bool fit_electrode_positions = true;  ///< (sheets with an analytic border)
  /// Levenberg–Marquardt's iterations (it stops before when the misfit changes by under 0.1 %).
  /// On some sheets the misfit creeps down a few per cent an iteration for many (a valley of the
  /// sheet's field against the series resistances, some of them at their bound of 0): on the
  /// realistic 60 mm twin, seed 7, χ² per reading 35 after 8 iterations, 7.6 after 20 (17 s);
  /// seed 3 stops by itself before 8.
  int max_iterations = 20;
  void validate() const;  ///< \throw InvalidInput naming the option
};

struct SensorCalibration {
  SheetCorrection correction;
  std::vector<double> series_resistance_ohm;  ///< per electrode (as the nominal sheet sees it)
  double drive_voltage_V = 0;
  std::vector<double> electrode_shift_mm;  ///< per electrode, along the border (counter-clockwise +)
  std::vector<CalibratedParameter> parameters;
  /// RMS of predicted − measured over the presses' readings [V], with each press at its true
  /// centre and its conductance fitted, on the nominal sensor and on the calibrated one; and the
  /// calibrated one's χ² per reading (about 1 when the model explains the presses to the noise).
  double rms_misfit_nominal_V = 0, rms_misfit_corrected_V = 0, chi2_per_reading = 0;
  int presses = 0;
  /// Per press, in the order given: its centre (the given one, or the fitted one where its place
  /// was unknown) and whether it was fitted.
  std::vector<Vector2> centres_mm;
  std::vector<bool> place_fitted;
  /// Plain-language doubts: a misfit far beyond the noise (the wrong sensor file, presses not
  /// where the truth says), a parameter at the edge of its plausible range.
  std::vector<std::string> warnings;
};

/// \param sensor      the nominal sensor (its own series resistances and drive are the start)
/// \param dV          per press, one value per measurement (frame − no-contact reference)
/// \param centres_mm  per press, its true centre; NaN where its place is unknown: that press's
///                    centre is then fitted with the sheet (each frame is N² readings against a
///                    handful of unknowns per press), started from the grid point of the nominal
///                    sheet whose disc's frame is nearest it
/// \param progress    told a line of news per iteration (may be empty)
/// \throw InvalidInput for fewer than 8 presses or a centre off the mesh; SolverError if the fit
///        fails.
SensorCalibration calibrate_sensor(const Sensor& sensor, const Mesh& fit_mesh, const MeasurementSet& measurements,
                                   const std::vector<Vector>& dV, const std::vector<Vector2>& centres_mm,
                                   const SensorCalibrationOptions& options = {}, const FitOptions& fit_options = {},
                                   const std::function<void(const std::string&)>& progress = {});

/// The same from calibration frames and their presses (`emit calibrate`'s inputs): the
/// single-press frames, less the no-contact reference, at their presses' centres.
SensorCalibration calibrate_sensor(const Sensor& sensor, const Mesh& fit_mesh, const MeasurementSet& measurements,
                                   const std::vector<Frame>& frames, const Frame& reference,
                                   const PressSequence& presses, const SensorCalibrationOptions& options = {},
                                   const std::function<void(const std::string&)>& progress = {});

/// The sensor as calibrated: its electrodes moved, its drive voltage and series resistances
/// replaced by the fitted ones.
Sensor calibrated_sensor(const Sensor& nominal, const SensorCalibration& calibration);

}  // namespace emit
