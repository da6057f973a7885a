#pragma once
/// \file sheet_correction.hpp
/// A real sheet's resistance is not uniform (coating thickness, stretch). The correction is a
/// smooth factor on the nominal sheet conductance, σ(x, y) = σ_nominal · exp(Σ θ_k b_k(u, v)),
/// with b = (u, v, u², uv, v²) and (u, v) the position scaled to [−1, 1] over `box`. It has no
/// constant term: a uniform factor on σ trades exactly against the contact conductance while the
/// contact's resistance dwarfs the sheet's spreading resistance (the frame scales as g/σ), so the
/// presses cannot tell it and the pressure calibration absorbs it. Fitted from presses by
/// sheet_calibration.hpp.
#include <array>

#include "emit/core/types.hpp"
#include "emit/mesh/mesh.hpp"

namespace emit {

struct SheetCorrection {
  static constexpr int terms = 5;
  Vector2 lower_mm = Vector2::Zero(), upper_mm = Vector2::Ones();  ///< the box (u, v) is scaled on
  std::array<double, terms> log_conductance{};                     ///< θ

  /// The uncorrected sheet over the mesh's bounding box.
  static SheetCorrection identity_over(const Mesh& mesh);

  /// b_k at a point.
  std::array<double, terms> basis(const Vector2& point_mm) const;
  /// σ / σ_nominal at a point.
  double factor(const Vector2& point_mm) const;
  /// Sheet conductance [S] per triangle of `mesh`, at its centroid.
  Vector element_conductance_S(const Mesh& mesh, double sheet_resistance_ohm_per_sq) const;
  /// The smallest and largest factor over the mesh's triangles.
  std::pair<double, double> factor_range(const Mesh& mesh) const;
};

}  // namespace emit
