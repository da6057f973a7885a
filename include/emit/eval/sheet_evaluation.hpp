#pragma once
/// \file sheet_evaluation.hpp
/// `emit eval` on one sheet (paper §3.2): frames from the twin on a finer, different mesh with the
/// ADC on (a jittered grid of single presses, presses of known pressure for calibration and
/// test, two-finger presses), reconstructed by each method (the linear ones over a λ² sweep, the
/// best kept, with the L-curve), and when the twin departs from the description in one way at a
/// time while the reconstruction keeps the nominal one (twin/sensor_mismatch.hpp).
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "emit/core/progress.hpp"
#include "emit/eval/contact_scoring.hpp"
#include "emit/eval/error_stats.hpp"
#include "emit/eval/evaluation.hpp"
#include "emit/model/method.hpp"
#include "emit/sensor/sensor.hpp"

namespace emit {

/// A sheet to evaluate and the presses to evaluate it with.
struct EvalCase {
  std::string name;
  Sensor sensor;
  double spacing_mm = 6, jitter_mm = 2, radius_mm = 5;  ///< the grid of single presses, the indenter
  std::string paper_position;                           ///< the paper's figure for it, for people
  bool pressure_and_two_press = true;                   ///< also calibrate pressure and try two fingers
  int lambdas_per_decade = 8;  ///< of the λ sweep (the 32-electrode sheet's operators cost 10× more)
};

/// The 60 mm, 30 mm, circle, 120 mm / 32-electrode sheets and the 25 mm dome (a spherical cap),
/// from the example sensors in `dir`.
std::vector<EvalCase> standard_eval_cases(const std::string& examples_dir);

struct EvalOptions {
  std::vector<Method> methods{Method::paper, Method::noser, Method::laplacian, Method::fit};
  std::vector<double> lambda2;  ///< the sweep; empty: 10⁰ … 10⁶, EvalCase::lambdas_per_decade a decade
  int mesh_seed = 3;            ///< the twin's mesh (another than the reconstruction's)
  std::uint64_t seed = 1;       ///< the presses and the ADC's noise
  bool quick = false;           ///< a coarser grid and fewer presses: a smoke test
  bool mismatches = true;       ///< also the sensor-mismatch runs (paper method and fit)
  void validate() const;        ///< \throw InvalidInput naming the option (core/option_check.hpp)
};

/// One λ² of a linear method's sweep.
struct SweepPoint {
  double lambda2 = 0;
  ErrorStats image_centroid, strongest_contact;  ///< the paper's estimate, and the strongest contact
  LCurvePoint l_curve;
};

struct MethodEvaluation {
  Method method = Method::paper;
  double lambda2 = 0;  ///< the best of the sweep (linear methods)
  /// Position: the paper's estimate at the best λ² (linear), the fitted contact (fit).
  ErrorStats position;
  ErrorStats strongest_contact;                    ///< the strongest contact's centroid
  std::optional<double> pressure_error_N_per_mm2;  ///< mean |error| after calibration on separate presses
  std::optional<TwoPressResult> two_press;         ///< matched within 0.4 × 4 radii (linear) or 2 mm (fit)
  /// Contact fitting: frames of three and of four presses (flat discs of the case's radius, every
  /// two at least the two-press runs' least separation apart, 4–16 N scaled by (r / 5 mm)²) with
  /// every press found within 2 mm; empty where the sheet has no room for them.
  std::optional<double> three_presses, four_presses;
  int several_press_frames = 0;  ///< of three, and as many of four
  /// Contact fitting: single presses (the grid's and the test presses) reported as more than one
  /// contact.
  std::optional<double> false_regions;
  int single_press_frames = 0;
  /// Linear methods: the test presses after `emit calibrate` on the calibration presses, as
  /// `emit reconstruct` reports them (force from emit's force law, model/force_law.hpp), and with
  /// eq. 8 alone (force Σ P_k A_k over the 50 % region, the image's: as before the force law).
  std::optional<SinglePressScore> calibrated, equation_8_forces;
  double ms_per_frame = 0;        ///< fit: the grid's frames
  long fit_mesh_nodes = 0;        ///< fit
  std::vector<SweepPoint> sweep;  ///< linear methods
  /// Linear methods with no λ² given: the automatic rule's λ² (model/lambda_rule.hpp), its
  /// positional error on the same frames, and the spectrum's scale (trace/M of J Q⁻¹ Jᵀ).
  double auto_lambda2 = 0, spectrum_scale = 0;
  ErrorStats auto_position;
  /// At the automatic λ²: single-press grid frames with a contact more than 2 press radii from the
  /// press, with the significance test and the resolution-cell floor (FrameOptions) and with
  /// every region above the threshold a contact (as before); no-press frames with any contact,
  /// the same two ways.
  double false_contacts = 0, false_contacts_untested = 0, noise_contacts = 0, noise_contacts_untested = 0;
  /// At the automatic λ²: the positional error's range over ten single-frame references, and with
  /// the ten averaged when one of them is very noisy (20 mV).
  double single_reference_low_mm = 0, single_reference_high_mm = 0, noisy_reference_mm = 0;
  std::optional<TwoPressResult> auto_two_press;  ///< at the automatic λ²
};

struct MismatchEvaluation {
  std::string name;
  ErrorStats paper;  ///< the paper's estimate
  bool dead_electrode_found = false;
  /// Contact fitting on the nominal sheet, and after the sheet's self-calibration from presses.
  std::optional<ErrorStats> fit, fit_self_calibrated;
  double sheet_factor_low = 1, sheet_factor_high = 1;  ///< the self-calibrated conductance's range
};

struct SheetEvaluation {
  std::size_t grid_presses = 0;
  long triangles = 0;  ///< the reconstruction mesh's
  std::vector<MethodEvaluation> methods;
  double mismatch_lambda2 = 0;  ///< the paper method's best, used for the mismatches
  std::vector<MismatchEvaluation> mismatches;
};

/// \throw InvalidInput for a bad case or option.
SheetEvaluation evaluate_sheet(const EvalCase& eval_case, const EvalOptions& options, const Progress& progress = {});

/// Error versus λ² and the L-curve (image norm versus misfit, λ² labelled every other decade) as
/// PNGs in `dir`, named after the case. \return their paths; none when no method swept λ².
std::vector<std::string> write_sweep_plots(const EvalCase& eval_case, const SheetEvaluation& evaluation,
                                           const std::string& dir);

}  // namespace emit
