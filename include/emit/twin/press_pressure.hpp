#pragma once
/// \file press_pressure.hpp
/// The pressure a press puts on the probing sheet as a function of the distance from its centre:
/// its indenter's profile (press.hpp), spread by the elastomer cover as a Gaussian of standard
/// deviation `blur_mm` (docs/physics.md, "The digital twin"). Blurred, the radial profile is the
/// 2-D convolution, tabulated once per press; unblurred, it is the indenter's profile exactly.
#include <vector>

#include "emit/sensor/press.hpp"

namespace emit {

class RadialPressure {
 public:
  /// \throw InvalidInput for a negative or non-finite blur.
  RadialPressure(const Press& press, double blur_mm);
  /// P at distance `distance_mm` from the centre [N/mm²]; 0 beyond support_mm().
  double at(double distance_mm) const;
  /// Where P ends: the radius, or radius + 4·blur (the Gaussian's tail beyond is < 4e-4 of it).
  double support_mm() const { return support_mm_; }
  /// Whether P is smooth (blurred), or has the flat indenter's jump at its rim.
  bool blurred() const { return !table_.empty(); }

 private:
  Press press_;
  double support_mm_ = 0;
  double step_mm_ = 0;
  std::vector<double> table_;  ///< P at k·step_mm_, k = 0 … (blurred only)
};

}  // namespace emit
