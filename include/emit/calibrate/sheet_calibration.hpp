#pragma once
/// \file sheet_calibration.hpp
/// Self-calibration of the sheet's resistance from presses at known places (issue 4: real sheets
/// differ from their description). A sheet 20 % more resistive on one side than the other moves
/// every fitted contact by millimetres, since the fit reads position from the shape of the
/// frame. Given presses whose centres are known (the calibration presses of `emit calibrate`),
/// the smooth correction of sheet_correction.hpp is fitted to all their frames at once by
/// Levenberg–Marquardt (Ceres), each press a disc held at its true centre with its own contact
/// conductance solved for (variable projection: the conductances are fitted inside each
/// evaluation, so the outer problem has the correction's five terms only).
#include <functional>
#include <string>
#include <vector>

#include "emit/frame/contact_fitter.hpp"
#include "emit/model/sheet_correction.hpp"
#include "emit/sensor/press.hpp"

namespace emit {

struct SheetCalibration {
  SheetCorrection correction;
  /// RMS of predicted − measured over the presses' readings [V], with the press at its true
  /// centre and its conductance fitted, on the nominal sheet and on the corrected one.
  double rms_misfit_nominal_V = 0, rms_misfit_corrected_V = 0;
  int presses = 0;
};

/// \param dV          per press, one value per measurement (frame − no-contact reference)
/// \param centres_mm  per press, its true centre
/// \param progress    told a line of news per iteration (may be empty)
/// \throw InvalidInput for fewer than 8 presses (five terms and the noise need more) or a centre
///        off the mesh; SolverError if the fit fails.
SheetCalibration calibrate_sheet(const Sensor& sensor, const Mesh& fit_mesh, const MeasurementSet& measurements,
                                 const std::vector<Vector>& dV, const std::vector<Vector2>& centres_mm,
                                 const FitOptions& options = {},
                                 const std::function<void(const std::string&)>& progress = {});

/// The same from calibration frames and their presses (`emit calibrate`'s inputs): the
/// single-press frames, less the no-contact reference, at their presses' centres.
SheetCalibration calibrate_sheet(const Sensor& sensor, const Mesh& fit_mesh, const MeasurementSet& measurements,
                                 const std::vector<Frame>& frames, const Frame& reference, const PressSequence& presses,
                                 const std::function<void(const std::string&)>& progress = {});

}  // namespace emit
