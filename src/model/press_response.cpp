#include "emit/model/press_response.hpp"

#include <cmath>

namespace emit {

Index response_basis_size(int degree) { return static_cast<Index>(degree + 1) * (degree + 2) / 2; }

void PressResponse::basis_at(const Vector2& p_mm, Eigen::Ref<Vector> basis) const {
  const double u = (p_mm.x() - center_mm.x()) / scale_mm, v = (p_mm.y() - center_mm.y()) / scale_mm;
  // Degree by degree, u^i v^(d−i) for i = 0 … d: each degree's terms from the previous degree's.
  Index k = 0;
  basis(k++) = 1;
  for (int d = 1; d <= degree; ++d) {
    const Index previous = k - d;                                      // the first of degree d − 1's d terms
    for (int i = 0; i < d; ++i) basis(k++) = basis(previous + i) * v;  // u^i v^(d−i)
    basis(k++) = basis(previous + d - 1) * u;                          // u^d
  }
}

double relative_change(const Eigen::Ref<const Vector>& frame, const Eigen::Ref<const Vector>& reference,
                       Eigen::Ref<Vector> change) {
  for (Index m = 0; m < frame.size(); ++m) {
    if (!(frame(m) > 0 && reference(m) > 0 && std::isfinite(frame(m)) && std::isfinite(reference(m)))) return 0;
    change(m) = std::log(frame(m) / reference(m));
  }
  const double norm = change.norm();
  if (!(norm > 0)) return 0;
  change /= norm;
  return norm;
}

}  // namespace emit
