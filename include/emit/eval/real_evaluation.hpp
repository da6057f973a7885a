#pragma once
/// \file real_evaluation.hpp
/// `emit eval --real`: touch localisation on a real current-injection skin's measured presses
/// (io/real_dataset.hpp), as its user would run it. The first N presses calibrate the skin's
/// press response (calibrate/press_response_fit.hpp: degree and shrinkage chosen by
/// cross-validation on those N only); every later press is located with it
/// (frame/press_locator.hpp); the error is reported on the held-out presses from `test_from` on,
/// and again for other numbers of calibration presses (the curve: what calibration buys).
#include <optional>
#include <string>
#include <vector>

#include "emit/calibrate/press_response_fit.hpp"
#include "emit/core/progress.hpp"
#include "emit/eval/error_stats.hpp"
#include "emit/frame/press_locator.hpp"
#include "emit/io/real_dataset.hpp"
#include "emit/model/reading_screen.hpp"
#include "emit/sensor/sensor.hpp"

namespace emit {

struct RealEvalOptions {
  Index calibration_presses = 100;  ///< N: the first N presses calibrate
  Index test_from = -1;             ///< the held-out presses; −1: the last fifth (440 of 550)
  /// The curve's numbers of calibration presses; those beyond test_from are left out.
  std::vector<Index> curve{20, 30, 50, 75, 100, 150, 200, 300, 440};
  PressResponseFitOptions fit;
  ReadingSurveyOptions readings;  ///< which readings to mask, which channels to drop (model/reading_screen.hpp)
  int grid_divisions = 70;        ///< the per-frame search's first grid (frame/press_locator.hpp)
  /// Also locate the held-out presses by the physics alone, with no calibration: the difference
  /// image of log(V/V_ref) (relative conductivity Jacobian on the sensor's mesh, NOSER prior,
  /// automatic λ), its centroid above half its largest magnitude (the paper's estimator).
  bool image = true;

  /// \throw InvalidInput naming the option, given the data set's number of presses; naming
  /// `folder` and the presses it needs when it holds too few for calibration and held-out presses.
  void validate(Index presses, const std::string& folder) const;
};

struct RealCurvePoint {
  Index calibration_presses = 0;
  ErrorStats held_out;          ///< on presses test_from …
  PressResponseCandidate kept;  ///< the calibration's choice, and its cross-validated error
};

struct RealEvaluation {
  Index presses = 0, readings = 0, test_from = 0, calibration_presses = 0;
  ReadingSurvey survey;  ///< the readings masked and the channels dropped, over every frame
  /// Calibration presses left out: none of their readings could be used, or they did not change.
  std::vector<Index> unusable_calibration_presses;
  PressResponseFit fit;                      ///< with calibration_presses
  ErrorStats held_out;                       ///< presses test_from …, located with `fit`
  ErrorStats held_out_centre;                ///< the same presses, always answering the calibration presses' centre
  std::optional<ErrorStats> held_out_image;  ///< the same, by the physics alone (RealEvalOptions::image)
  long image_triangles = 0;                  ///< its mesh's
  std::vector<LocatedPress> located;         ///< presses calibration_presses …, in order
  std::vector<RealCurvePoint> curve;
  double ms_per_frame = 0;  ///< locating one frame (the held-out presses' mean)
  /// The held-out presses found whose error is within their own σ (LocatedPress::std_mm), and 2σ.
  double within_1sigma = 0, within_2sigma = 0;
  double held_out_sigma_mm = 0;  ///< their σ's mean
};

/// Readings that cannot be trusted are masked, frame by frame, and channels bad in most frames
/// dropped (model/reading_screen.hpp); a press whose readings are all unusable is left out.
/// \throw InvalidInput when the data's frames do not have the sensor's readings (its
/// "excitation"), when a frame holds more than one press, or as the options' validate().
RealEvaluation evaluate_real(const RealDataset& data, const Sensor& sensor, const RealEvalOptions& options,
                             const Progress& progress = {});

}  // namespace emit
