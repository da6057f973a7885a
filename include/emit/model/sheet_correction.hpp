#pragma once
/// \file sheet_correction.hpp
/// A real sheet's resistance is not uniform (coating thickness, stretch). The correction is a
/// smooth factor on the nominal sheet conductance, σ(x, y) = σ_nominal · exp(Σ θ_k b_k(u, v)),
/// with b = (u, v, u², uv, v²) (quadratic, 5 terms) or those and (u³, u²v, uv², v³) (cubic, 9
/// terms), and (u, v) the position scaled to [−1, 1] over `box`. It has no
/// constant term: a uniform factor on σ trades exactly against the contact conductance while the
/// contact's resistance dwarfs the sheet's spreading resistance (the frame scales as g/σ), so the
/// presses cannot tell it and the pressure calibration absorbs it. Fitted from presses by
/// sensor_calibration.hpp.
#include <vector>

#include "emit/core/types.hpp"
#include "emit/mesh/mesh.hpp"

namespace emit {

struct SheetCorrection {
  static constexpr int quadratic_terms = 5, cubic_terms = 9;
  Vector2 lower_mm = Vector2::Zero(), upper_mm = Vector2::Ones();                   ///< the box (u, v) is scaled on
  std::vector<double> log_conductance = std::vector<double>(quadratic_terms, 0.0);  ///< θ: 5 or 9 terms

  /// The uncorrected sheet over the mesh's bounding box, with `terms` (5 or 9) terms.
  static SheetCorrection identity_over(const Mesh& mesh, int terms = quadratic_terms);

  int terms() const { return static_cast<int>(log_conductance.size()); }
  /// b_k at a point, k < terms().
  std::vector<double> basis(const Vector2& point_mm) const;
  /// σ / σ_nominal at a point.
  double factor(const Vector2& point_mm) const;
  /// Sheet conductance [S] per triangle of `mesh`, at its centroid.
  Vector element_conductance_S(const Mesh& mesh, double sheet_resistance_ohm_per_sq) const;
  /// The smallest and largest factor over the mesh's triangles.
  std::pair<double, double> factor_range(const Mesh& mesh) const;
};

}  // namespace emit
