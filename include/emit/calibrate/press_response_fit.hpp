#pragma once
/// \file press_response_fit.hpp
/// A current-injection skin's press response (model/press_response.hpp) fitted to presses of
/// known place: for each candidate (a degree, or a kernel's width and smoothing) and shrinkage, W by least squares (a
/// ridge of 1e-6 per press keeps a degree with more terms than presses solvable), Λ from the residuals' covariance S as
/// ((1 − ρ) S + ρ diag S)⁻¹; the candidate kept is the one whose presses are located best by k-fold cross-validation
/// (each fold located by a model fitted without it, frame/press_locator.hpp). The region searched is the calibration
/// presses' convex hull. Nothing is tuned on presses outside the calibration set.
///
/// Masked readings (NaN in a press's change; model/reading_screen.hpp) are filled from the model
/// at the press's known place (a first fit of the lowest degree, its amplitude fitted to the
/// press's readings used), twice, before the candidates are fitted; the cross-validation locates
/// a held-out press with them masked, as a frame is located.
///
/// The drift rate (frame/press_locator.hpp, "Drift") is chosen as a live session would have
/// chosen it: the kept candidate fitted on the first half of the presses (in the order measured),
/// the second half located in order with each rate; the fastest rate whose paired excess error
/// over the best rate's is within one standard error is kept (half a calibration is too short for
/// most drift to show: tracking costs little on a skin that holds still, and gains much on one
/// that drifts).
/// The position σ's scale (frame/press_locator.hpp, "How sure") is set on the same half: the least
/// that puts 68 % of its errors within 1σ and 95 % within 2σ (split conformal).
#include <vector>

#include "emit/core/progress.hpp"
#include "emit/core/types.hpp"
#include "emit/model/press_response.hpp"

namespace emit {

struct PressResponseFitOptions {
  std::vector<int> degrees{2, 3, 4, 5, 6};
  std::vector<double> shrinkages{0.1, 0.3, 0.6, 1.0};  ///< ρ, each in [0, 1]
  /// Kernel responses (model/press_response.hpp): a plane plus bumps of each width ℓ on a lattice
  /// of spacing ℓ, their coefficients a held to the prior λ n aᵀKa (K the bumps' kernel between
  /// their centres: a Gaussian process's smoothness) for each λ; every ρ with each. Empty: none.
  std::vector<double> kernel_lengths_mm{20, 30, 40};
  std::vector<double> kernel_smoothings{1e-4, 1e-3};  ///< λ, each positive
  int folds = 10;                                     ///< for the cross-validation; at most the number of presses
  int grid_divisions = 35;  ///< the cross-validation's location grid (coarser than per frame's 70)
  std::vector<double> drift_rates{0, 0.01, 0.03, 0.1};  ///< each in [0, 1)

  /// \throw InvalidInput naming the option and the rule it breaks.
  void validate() const;
};

struct PressResponseCandidate {
  int degree = 0;
  double shrinkage = 0;
  double kernel_length_mm = 0;    ///< 0: monomials alone
  double smoothing = 0;           ///< λ of a kernel response
  double cross_validated_mm = 0;  ///< mean position error of the held-out folds
};

struct PressResponseFit {
  PressResponse response;
  PressResponseCandidate kept;                     ///< the one `response` is
  std::vector<PressResponseCandidate> candidates;  ///< every one tried, the kept one among them
  double drift_rate = 0;                           ///< the one chosen
  std::vector<double> drift_errors_mm;             ///< per drift_rates: the second half's mean error
  Index filled_presses = 0;                        ///< presses with masked readings filled
};

/// changes: one row per press in the order measured, its change (relative_change's, normalised,
/// NaN where masked; the fit itself takes any scale); positions_mm: its centre. \throw InvalidInput for fewer than 2 ×
/// folds presses, or rows and positions that differ in number.
PressResponseFit fit_press_response(const Matrix& changes, const std::vector<Vector2>& positions_mm,
                                    const PressResponseFitOptions& options = {}, const Progress& progress = {});

}  // namespace emit
