#pragma once
/// \file press_locator.hpp
/// Where a current-injection skin was pressed, from a learned press response
/// (model/press_response.hpp): the centre p that maximises the likelihood with a free amplitude,
///   score(p) = (dᵀΛm(p))² / (m(p)ᵀΛm(p))  for dᵀΛm(p) > 0,
/// searched on a grid over the response's region, then refined about the best grid point on
/// finer and finer grids (the score is smooth in p). Both terms are quadratic forms in the
/// basis b(p) (B monomials): dᵀΛm = (WΛd)ᵀb and mᵀΛm = bᵀ(WΛWᵀ)b, so with WΛWᵀ and the grid's
/// b formed once, a frame costs one M × M and one B × M product, one G × B (G grid points) and
/// B² per refinement point, and allocates nothing.
///
/// **Masked readings** (model/reading_screen.hpp): a reading that cannot be trusted is
/// marginalised out of the frame's likelihood. For the Gaussian of precision Λ, leaving out the
/// readings 𝓑 is the Schur complement Λ' = Λ − Λ_{·𝓑} Λ_{𝓑𝓑}⁻¹ Λ_{𝓑·}: a rank-k change, so with
/// C = WΛ_{·𝓑} and Λ_{𝓑𝓑} = LLᵀ, WΛ'Wᵀ = WΛWᵀ − ZZᵀ, Z = CL⁻ᵀ, and each grid point's mᵀΛ'm loses
/// ‖Zᵀb‖²: k × (B·M + G·B) more a frame, in scratch sized once (up to `max_masked` readings).
///
/// **Drift** (`drift_rate` f > 0): a skin's response drifts after its calibration (the hydrogel's
/// residual from the calibrated response grows over the hours of a session). The locator keeps
/// δ, an exponential average of the residuals d − a m(p̂) of the presses it has located, and
/// locates each new frame's d − δ; δ ← (1 − f) δ + f (d − a m(p̂)), a the least-squares amplitude.
/// It learns from located frames only (no true places): the order of frames then matters, as in
/// a live session.
///
/// **How sure**: a press the model places badly is one it explains badly: on the hydrogel skin the
/// error's correlation with √(1 − explained) is 0.37, while the likelihood's own spread over the
/// grid, at any temperature, does not follow the error at all (0.0–0.2; Λ, fitted to 100 presses,
/// knows the noise, not the model's error). So the position's σ is k √(1 − explained + u₀), the
/// floor u₀ for a press explained well but placed off by the model's own bias; k and u₀ set on
/// presses the fit did not see (calibrate/press_response_fit.hpp); along each axis σ/√2.
#include "emit/core/types.hpp"
#include "emit/model/press_response.hpp"
#include "emit/model/reading_screen.hpp"

namespace emit {

struct LocatedPress {
  bool found = false;  ///< false: the frame did not change, or too few of its readings could be used
  Vector2 position_mm{0, 0};
  /// The frame's change from its reference, rms over the readings used: ‖log(V / V_ref)‖ / √M' (the
  /// hydrogel's presses change it by 1 – 3 %; model/press_response.hpp).
  double relative_change_rms = 0;
  /// How much of the change the model explains, in Λ's metric: (dᵀΛm)² / (mᵀΛm · dᵀΛd), in [0, 1].
  double explained = 0;
  int masked = 0;  ///< readings left out of this frame (not counting channels dropped for good)
  /// The position's σ ("How sure" above), of the distance to the true place, and along x and y
  /// (std_mm / √2 each); 0 when the response has no error scale.
  double std_mm = 0, x_std_mm = 0, y_std_mm = 0;
};

struct PressLocatorOptions {
  /// The first search's grid spaces this many steps across the region's larger extent (70: 2 mm
  /// on the hydrogel's 140 mm); the refinement then halves the step five times.
  int grid_divisions = 70;
  /// f, the weight of each located press in the drift's average; 0: no drift (each frame alone).
  double drift_rate = 0;
  ReadingScreen screen;  ///< which readings to leave out
  /// A frame with more masked readings than this (−1: a quarter of them) is not located.
  Index max_masked = -1;

  /// \throw InvalidInput naming the option.
  void validate() const;
};

class PressLocator {
 public:
  /// \throw InvalidInput for fewer than 2 divisions or a response with no region.
  explicit PressLocator(PressResponse response, int grid_divisions = 70);
  /// \throw InvalidInput as options.validate(), or for a screen of another number of readings.
  PressLocator(PressResponse response, PressLocatorOptions options);

  /// frame and reference: M values each (model/press_response.hpp); readings the screen refuses
  /// are masked. Updates the drift when the press is found. \throw InvalidInput for a wrong
  /// size (the only check that allocates, on the error path).
  LocatedPress locate(const Eigen::Ref<const Vector>& frame, const Eigen::Ref<const Vector>& reference);

  /// The same for a change already formed (relative_change: unit norm over the readings used,
  /// NaN where masked, M values).
  LocatedPress locate_change(const Eigen::Ref<const Vector>& change);

  /// Forgets the drift learned so far.
  void reset_drift() { drift_.setZero(); }
  const Vector& drift() const { return drift_; }

  const PressResponse& response() const { return response_; }
  Index grid_points() const { return grid_mm_.cols(); }

 private:
  /// The search for change_ (NaN where masked).
  LocatedPress locate_normalised();
  /// Marginalises the masked readings bad_[0 … k) out: fills weighted_change_ (Λ'd), the masked
  /// gram and grid norms. \return dᵀΛ'd.
  double marginalise(Index k);
  /// The score at p (−1 where dᵀΛm ≤ 0), from projected_change_ and *gram_now_; fills basis_.
  double score_at(const Vector2& p_mm);
  void learn_drift(const Vector2& p_mm);

  PressResponse response_;
  PressLocatorOptions options_;
  Eigen::Matrix2Xd grid_mm_;  ///< 2 × G
  Matrix gram_;               ///< WΛWᵀ, B × B
  Matrix grid_basis_;         ///< G × B: row g = b(p_g)ᵀ
  Vector grid_norm2_;         ///< G: m(p_g)ᵀ Λ m(p_g)
  double grid_step_mm_ = 0;
  Index max_masked_ = 0;
  // Per-frame scratch, sized once.
  Vector change_, used_change_, weighted_change_, projected_change_, grid_scores_, basis_, gram_basis_;
  Vector model_, drift_;
  Eigen::Matrix<Index, Eigen::Dynamic, 1> bad_;  ///< the masked readings' indices
  Matrix masked_block_, masked_z_, masked_grid_, masked_gram_;
  Vector masked_y_, masked_norm2_;
  const Matrix* gram_now_ = &gram_;  ///< gram_ or masked_gram_
  const Vector* grid_norm2_now_ = &grid_norm2_;
};

}  // namespace emit
