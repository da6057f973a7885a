#pragma once
/// \file lambda_rule.hpp
/// λ² chosen from the operator's own spectrum (docs/physics.md, "How λ is chosen"): a fixed
/// multiple of the second eigenvalue of J Q⁻¹ Jᵀ. The largest is the common mode (a press raises
/// every reading), ~98 % of the trace, and says how much the whole sheet's potential moves; the
/// second (a pair, the dipole modes) is the first spatial mode, and the paper method's 50 %
/// threshold centres on the press when λ² filters it by about half. Relative to it the best λ² is
/// the same on every sheet (`emit eval`, the paper method: 1.77–1.83 σ₂ on the 60 mm, 30 mm and
/// circle sheets, 1.36 σ₂ on the 120 mm / 32-electrode sheet), and it follows the Jacobian's
/// scale wherever that changes, so the rule needs no tuning.
#include "emit/core/types.hpp"

namespace emit {

/// The second-largest eigenvalue of J Q⁻¹ Jᵀ: the scale λ² is measured against. 0 for fewer
/// than two eigenvalues.
double spectrum_scale(const Vector& eigenvalues);

/// λ² = relative · spectrum_scale. \throw InvalidInput for a non-positive `relative` or a
/// spectrum whose scale is not positive.
double automatic_lambda2(const Vector& eigenvalues, double relative);

}  // namespace emit
