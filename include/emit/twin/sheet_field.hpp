#pragma once
/// \file sheet_field.hpp
/// A sheet whose resistance varies smoothly and at random, as a printed or sprayed sheet does
/// (docs/physics.md, "The digital twin"): Rs(x, y) = Rs · exp(f(x, y)), f a sum of a few random
/// Fourier modes of wavelength at least half the sheet's size, scaled so that max |f| over the
/// sheet is log(1 + amplitude) (amplitude 0.15: from 1/1.15 to 1.15 times Rs).
#include <cstdint>
#include <vector>

#include "emit/core/types.hpp"
#include "emit/sensor/border.hpp"

namespace emit {

class SheetField {
 public:
  /// `modes` random modes, seeded. \throw InvalidInput for an amplitude outside [0, 1) or no modes.
  SheetField(const Border& border, double amplitude, std::uint64_t seed, int modes = 6);
  /// exp(f(p)): the factor on the sheet resistance at p.
  double factor(const Vector2& p_mm) const;
  /// The factor's smallest and largest values over the sheet (sampled on a 96 × 96 grid).
  double min_factor() const { return min_factor_; }
  double max_factor() const { return max_factor_; }

 private:
  struct Mode {
    Vector2 wavevector_per_mm;
    double phase, weight;
  };
  double log_factor(const Vector2& p_mm) const;
  std::vector<Mode> modes_;
  double min_factor_ = 1, max_factor_ = 1;
};

}  // namespace emit
