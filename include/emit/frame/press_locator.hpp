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
#include "emit/core/types.hpp"
#include "emit/model/press_response.hpp"

namespace emit {

struct LocatedPress {
  bool found = false;  ///< false: the frame did not change, or a value was not positive and finite
  Vector2 position_mm{0, 0};
  /// The frame's change from its reference, rms over the readings: ‖log(V / V_ref)‖ / √M (the
  /// hydrogel's presses change it by 1 – 3 %; model/press_response.hpp).
  double relative_change_rms = 0;
  /// How much of the change the model explains, in Λ's metric: (dᵀΛm)² / (mᵀΛm · dᵀΛd), in [0, 1].
  double explained = 0;
};

class PressLocator {
 public:
  /// The first search's grid spaces `grid_divisions` steps across the region's larger extent
  /// (70: 2 mm on the hydrogel's 140 mm); the refinement then halves the step five times.
  /// \throw InvalidInput for fewer than 2 divisions or a response with no region.
  explicit PressLocator(PressResponse response, int grid_divisions = 70);

  /// frame and reference: M values each (model/press_response.hpp). \throw InvalidInput for a
  /// wrong size (the only check that allocates, on the error path).
  LocatedPress locate(const Eigen::Ref<const Vector>& frame, const Eigen::Ref<const Vector>& reference);

  /// The same for a change already formed (relative_change: unit norm, M values).
  LocatedPress locate_change(const Eigen::Ref<const Vector>& change);

  const PressResponse& response() const { return response_; }
  Index grid_points() const { return grid_mm_.cols(); }

 private:
  /// The search for change_.
  LocatedPress locate_normalised();
  /// The score at p (−1 where dᵀΛm ≤ 0), from projected_change_; fills basis_ and gram_basis_.
  double score_at(const Vector2& p_mm);

  PressResponse response_;
  Eigen::Matrix2Xd grid_mm_;  ///< 2 × G
  Matrix gram_;               ///< WΛWᵀ, B × B
  Matrix grid_basis_;         ///< G × B: row g = b(p_g)ᵀ
  Vector grid_norm2_;         ///< G: m(p_g)ᵀ Λ m(p_g)
  double grid_step_mm_ = 0;
  // Per-frame scratch, sized once.
  Vector change_, weighted_change_, projected_change_, grid_scores_, basis_, gram_basis_;
};

}  // namespace emit
