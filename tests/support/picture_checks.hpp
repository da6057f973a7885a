#pragma once
// Checks shared by the tests of the pictures (tests/render).
#include <algorithm>
#include <cmath>

namespace emit::test {

/// How far a scale bar `length_px` long is from a round length (1, 2 or 5 × 10^k mm) at
/// `px_per_mm` [px]: a picture's scale bar is within its two end pixels of one.
inline double px_from_round_length(int length_px, double px_per_mm) {
  const double length_mm = length_px / px_per_mm, decade = std::pow(10.0, std::floor(std::log10(length_mm)));
  double nearest_mm = 1e9;
  for (const double m : {1.0, 2.0, 5.0, 10.0}) nearest_mm = std::min(nearest_mm, std::abs(length_mm - m * decade));
  return nearest_mm * px_per_mm;
}

}  // namespace emit::test
