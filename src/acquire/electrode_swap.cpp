#include "emit/acquire/electrode_swap.hpp"

namespace emit {

double border_roughness(const Frame& frame, int a, int b) {
  const auto n = static_cast<int>(frame.rows());
  // Place k of the border holds electrode wired(k): the frame as if a and b were exchanged.
  const auto wired = [a, b](int k) { return k == a ? b : k == b ? a : k; };
  double sum = 0;
  for (int l = 0; l < n; ++l) {
    const int row = wired(l);
    for (int m = 0; m < n; ++m) {
      const int before = (m + n - 1) % n, after = (m + 1) % n;
      if (l == before || l == m || l == after) continue;  // the grounded electrode's own dip
      const double d = frame(row, wired(m)) - 0.5 * (frame(row, wired(before)) + frame(row, wired(after)));
      sum += d * d;
    }
  }
  return sum;
}

SwapCandidate best_swap(const Frame& frame) {
  SwapCandidate best;
  const double as_read = border_roughness(frame);
  if (!(as_read > 0)) return best;
  const auto n = static_cast<int>(frame.rows());
  for (int a = 0; a < n; ++a)
    for (int b = a + 1; b < n; ++b) {
      const double ratio = border_roughness(frame, a, b) / as_read;
      if (ratio < best.roughness_ratio) best = {a, b, ratio};
    }
  return best;
}

}  // namespace emit
