#pragma once
/// \file resolvability_study.hpp
/// `emit eval --resolvability`: what a frame of the sheet can tell (eval/resolvability.hpp),
/// against the place on the sheet: the Cramér–Rao bound on a round press's centre, radius and
/// force against its radius; the smallest gap at which two parallel bars are told from one; how
/// clearly a ring's hole shows. The numbers docs/physics.md, "What a frame can tell", gives.
#include <vector>

#include "emit/core/progress.hpp"
#include "emit/eval/resolvability.hpp"

namespace emit {

struct ResolvabilityOptions {
  /// Distances from the sheet's centre along +x (towards the middle of a side on a square).
  std::vector<double> offsets_mm{0, 8, 16, 20};
  std::vector<double> radii_mm{2, 3, 4, 6, 8, 10, 12};          ///< round presses
  double force_N = 8;                                           ///< of each round press
  double bar_width_mm = 3, bar_length_mm = 20;                  ///< the two parallel bars (a ruler's edge)
  std::vector<double> gaps_mm{0.5, 1, 1.5, 2, 3, 4, 6, 8, 10};  ///< ascending
  double ring_outer_mm = 9;                                     ///< a bottle's rim: 12–18 mm across
  std::vector<double> ring_inner_mm{2, 4, 6, 7};
  double pressure_N_per_mm2 = 0.1;  ///< of the bars and rings
  double clearance_mm = 1;          ///< every region this far inside the border at least
  int reference_frames = 10;
  void validate() const;  ///< \throw InvalidInput naming the option (core/option_check.hpp)
};

/// Few enough for a test or a smoke run.
ResolvabilityOptions quick_resolvability_options();

struct ResolvabilityStudy {
  Vector2 centre_mm{0, 0};
  double noise_V = 0;
  std::vector<double> offsets_mm, radii_mm, gaps_mm, ring_inner_mm;
  /// [radius][offset]; a press that does not fit there: NaN in every field.
  std::vector<std::vector<RoundContactBound>> round;
  /// [gap][offset]: Δχ² of two bars against the best single bar (NaN where they do not fit).
  std::vector<std::vector<double>> gap_delta_chi2;
  /// [offset]: the smallest gap from which every larger one reaches Resolvability::resolved_delta_chi2
  /// (NaN: none of those tried).
  std::vector<double> resolvable_gap_mm;
  /// [inner radius][offset]: Δχ² of the ring against the best full disc.
  std::vector<std::vector<double>> ring_delta_chi2;
  /// The same three with the alternative held at the outline's own pressure (a prior that knows it).
  std::vector<std::vector<double>> gap_delta_chi2_held, ring_delta_chi2_held;
  std::vector<double> resolvable_gap_held_mm;
};

/// On the flat sheet of `sensor`, whose fit model is `fit`. \throw InvalidInput (a curved sheet,
/// a bad option).
ResolvabilityStudy study_resolvability(const Sensor& sensor, const FitModel& fit, const ResolvabilityOptions& options,
                                       const Progress& progress = {});

}  // namespace emit
