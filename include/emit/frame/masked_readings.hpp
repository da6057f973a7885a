#pragma once
/// \file masked_readings.hpp
/// A frame's readings that cannot be trusted, left out of its image exactly (docs/physics.md,
/// "Bad readings"). A reading is masked when it or its reference is not finite (a file's `nan`, a
/// reading never seen in the reference frames) or it sits at the ADC's top code (clipped: the true
/// value is higher, by an unknown amount).
///
/// The linear methods image δφ = R·δV with R = Q⁻¹Jᵀ P, P = (J Q⁻¹ Jᵀ + λ² I)⁻¹ (paper eq. 7 in
/// measurement space). P is the precision of the Gaussian prior δV ~ N(0, P⁻¹) the operator
/// implies, and a masked set 𝓜 of readings is replaced by its mean given the others 𝓤,
///   δV̂_𝓜 = −P_𝓜𝓜⁻¹ P_𝓜𝓤 δV_𝓤,
/// which sets (P·δV̂)_𝓜 = 0 and (P·δV̂)_𝓤 = (P⁻¹)_𝓤𝓤⁻¹ δV_𝓤: R·δV̂ is then exactly the image of the
/// operator built from the rows 𝓤 alone, with no operator rebuilt. Contact fitting sees the filled
/// frame too. Per frame: k·M + k³/3 for k masked readings, in scratch sized once.
#include <vector>

#include <Eigen/Core>

#include "emit/core/types.hpp"

namespace emit {

class MaskedReadingFill {
 public:
  /// Scratch for frames of `readings` readings with up to `max_masked` of them masked.
  MaskedReadingFill(Index readings, Index max_masked);

  /// dV's entries at `masked` (distinct indices; their values are ignored) ← their mean given the
  /// others under `precision` (CompactOperator::precision). Allocates nothing.
  /// \throw InvalidInput if precision is not readings by readings or more than max_masked are masked.
  void fill(const Eigen::MatrixXf& precision, const std::vector<Index>& masked, Vector& dV);

  Index max_masked() const { return factor_.rows(); }

 private:
  Matrix factor_;  ///< the Cholesky factor of P_𝓜𝓜
  Vector rhs_;     ///< P_𝓜𝓤 δV_𝓤, then the fill
};

}  // namespace emit
