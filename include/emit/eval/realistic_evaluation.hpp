#pragma once
/// \file realistic_evaluation.hpp
/// `emit eval --realistic`: the round a user runs with a real sheet (README, "A realistic
/// sheet"), on the twin's realistic sheet (twin/realistic_sheet.hpp: every way a real sheet departs
/// from its description at once), measured against its targets (RealisticTargets). On one sheet:
///
/// 1. a realistic sheet drawn from a seed, its twin on a mesh of another seed than the
///    reconstruction's; a reference of no-press frames, calibration presses and test presses of
///    one flat indenter at random places (the README's round: the same seeds, the same frames);
/// 2. the calibration `emit calibrate` makes, with its defaults (pipeline/press_calibration.hpp);
///    the test presses reconstructed by contact fitting (Pipeline) with the nominal description
///    and with that calibration;
/// 3. with the calibration: presses of other indenters (flat and spherical, 3 to 10 mm), and
///    frames of three and of four presses at least 12 mm apart;
/// 4. the paper method calibrated as `emit calibrate --method paper` does on the same presses, its
///    forces on the test presses and the other indenters.
///
/// Lengths scale with the sheet's indenter (EvalCase::radius_mm / 5 mm) and forces with its
/// square, so every sheet sees the 60 mm sheet's pressures.
#include <cstdint>
#include <string>
#include <vector>

#include "emit/core/progress.hpp"
#include "emit/eval/contact_scoring.hpp"
#include "emit/eval/parameter_truth.hpp"
#include "emit/eval/sheet_evaluation.hpp"
#include "emit/twin/realistic_sheet.hpp"

namespace emit {

/// How many frames of each kind.
struct RealisticEvalCounts {
  int reference_frames = 10;      ///< no-press frames, averaged into the reference
  int calibration_presses = 40;   ///< the calibration's (least_calibration_presses or more)
  int test_presses = 60;          ///< of the calibration's indenter
  int presses_per_indenter = 10;  ///< each other indenter: 5 radii × 2 profiles
  int multi_press_frames = 20;    ///< of three presses, and as many of four
  /// The sensor calibration's most iterations (SensorCalibrationOptions::max_iterations); 0:
  /// `emit calibrate`'s own. Each costs a Green's function per sheet term and electrode shift.
  int calibration_iterations = 0;
};

/// Counts for a smoke test (`emit eval --realistic --quick`): the calibration's 40 presses, but
/// its sensor fit stopped after 2 iterations; a few frames of every other kind, each figure
/// scored, too few to judge by.
RealisticEvalCounts quick_realistic_counts();

struct RealisticEvalOptions {
  /// What the sheet departs by, and its seed (`--realistic SEED`; 3, the README's round).
  RealisticSheetOptions sheet{.seed = 3};
  int mesh_seed = 3;  ///< the twin's mesh (another than the reconstruction's)
  /// The reference's noise; the calibration presses and their noise use seed + 1, the test
  /// presses seed + 2 (the README's round: 11, 12, 13); the other indenters and the presses of
  /// several fingers are drawn from seed + 3 on, with one noise (seed + 3).
  std::uint64_t seed = 11;
  RealisticEvalCounts counts;
  /// > 0: calibrate as in the field (`emit eval --realistic --unplaced K`): every calibration
  /// press's place forgotten and only the first K presses' forces kept (a few known weights put
  /// down anywhere); the targets are then UnplacedTargets'. 0: every place and force known.
  int unplaced_known_forces = 0;
  void validate() const;  ///< \throw InvalidInput naming the count or the sheet's option
};

/// The realistic round's targets (README, "A realistic sheet"), the figures they bound.
struct RealisticTargets {
  static constexpr double position_mean_mm = 0.3, position_p95_mm = 0.6;  ///< calibrated, test presses
  static constexpr double pressure_error_N_per_mm2 = 0.01;                ///< calibrated, mean |error|
  static constexpr double force_error = 0.10;                             ///< the same indenter
  static constexpr double other_indenters_force_error = 0.15;
  static constexpr double within_1_sigma = 0.68, within_2_sigma = 0.95;  ///< other indenters
  static constexpr double three_presses = 0.95, four_presses = 0.90;     ///< every press matched
  static constexpr double false_contacts = 0.02;                         ///< of single presses
  static constexpr double calibration_s = 60;
  /// The sensor calibration's parameters within their reported 2σ of the truth (over many sheets).
  static constexpr double parameters_within_2_sigma = 0.95;
};

/// The field calibration's targets (issue "calibrate a sheet where it is used"): presses at unknown
/// places, a few of known force.
struct UnplacedTargets {
  static constexpr double position_mean_mm = 0.5, position_p95_mm = 1.0;
  static constexpr double pressure_error_N_per_mm2 = 0.02;
};

/// One other indenter, `presses_per_indenter` presses of it.
struct IndenterScore {
  double radius_mm = 0;
  PressProfile profile = PressProfile::flat;
  SinglePressScore score;
};

struct RealisticEvaluation {
  std::string sheet_description;  ///< what the sheet drew (RealisticSheet::description)
  long triangles = 0;             ///< the reconstruction mesh's
  RealisticEvalCounts counts;
  int unplaced_known_forces = 0;         ///< RealisticEvalOptions's: > 0, calibrated as in the field
  double radius_mm = 5;                  ///< the calibration's and the test presses' indenter (flat)
  double match_mm = 2;                   ///< a press of several is found when a contact of its own is this close
  double separation_mm = 12;             ///< the least distance between two presses of a frame of several
  SinglePressScore nominal, calibrated;  ///< the test presses, with the nominal file and calibrated
  std::vector<IndenterScore> indenters;  ///< calibrated
  SinglePressScore other_indenters;      ///< all of them at once
  /// Fractions of frames with every press matched (every_press_matched), calibrated.
  double three_presses = 0, four_presses = 0;
  /// False contacts over every calibrated single press (test presses and other indenters).
  int false_contacts = 0, single_presses = 0;
  /// The paper method after `emit calibrate --method paper` on the same presses (its force law,
  /// model/force_law.hpp): the test presses, the other indenters, and the test presses with eq. 8
  /// alone (force Σ P_k A_k over the 50 % region, as before the force law).
  SinglePressScore paper, paper_other_indenters, paper_equation_8;
  double calibration_s = 0;         ///< wall time of the calibration (calibrate_from_presses)
  double fit_ms_per_frame = 0;      ///< wall time a calibrated test frame (one press)
  double several_ms_per_frame = 0;  ///< and a frame of three or four presses
  std::vector<std::string> calibration_warnings;
  /// The sensor calibration's parameters against the sheet's truth in their own terms
  /// (parameter_truth.hpp): how often the reported σ covers it.
  ParameterCoverage sheet_parameters;
};

/// The round on `eval_case`'s sheet (its sensor must have an analytic border). `progress` is told
/// each stage and the frames as they are simulated and reconstructed.
/// \throw InvalidInput for bad options or a sheet without room for four presses; SolverError.
RealisticEvaluation evaluate_realistic_sheet(const EvalCase& eval_case, const RealisticEvalOptions& options,
                                             const Progress& progress = {});

}  // namespace emit
