#include "emit/model/press_response.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace emit {

Index response_basis_size(int degree) { return static_cast<Index>(degree + 1) * (degree + 2) / 2; }

Index PressResponse::basis_size() const { return response_basis_size(degree) + static_cast<Index>(centres_mm.size()); }

std::vector<Vector2> hexagonal_lattice(const Vector2& centre_mm, double radius_mm, double spacing_mm) {
  std::vector<Vector2> points;
  const double row_step = spacing_mm * std::sqrt(3.0) / 2;
  const int rows = static_cast<int>(std::floor(radius_mm / row_step)),
            columns = static_cast<int>(std::floor(radius_mm / spacing_mm)) + 1;
  for (int j = -rows; j <= rows; ++j)
    for (int i = -columns; i <= columns; ++i) {
      const Vector2 offset((i + (j % 2 != 0 ? 0.5 : 0.0)) * spacing_mm, j * row_step);
      if (offset.norm() <= radius_mm) points.emplace_back(centre_mm + offset);
    }
  return points;
}

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
  const double scale = -0.5 / (kernel_length_mm * kernel_length_mm);
  for (const Vector2& c : centres_mm) basis(k++) = std::exp(scale * (p_mm - c).squaredNorm());
}

bool PressResponse::in_region(const Vector2& p_mm) const {
  if (region_mm.size() < 3) return false;
  for (std::size_t i = 0; i < region_mm.size(); ++i) {
    const Vector2& a = region_mm[i];
    const Vector2& b = region_mm[(i + 1) % region_mm.size()];
    const Vector2 edge = b - a, to_p = p_mm - a;
    // Left of every counter-clockwise edge, to 1e-9 mm.
    if (edge.x() * to_p.y() - edge.y() * to_p.x() < -1e-9 * edge.norm()) return false;
  }
  return true;
}

std::vector<Vector2> convex_hull(std::vector<Vector2> points) {
  std::sort(points.begin(), points.end(),
            [](const Vector2& a, const Vector2& b) { return a.x() < b.x() || (a.x() == b.x() && a.y() < b.y()); });
  points.erase(std::unique(points.begin(), points.end()), points.end());
  if (points.size() < 3) return points;
  const auto cross = [](const Vector2& o, const Vector2& a, const Vector2& b) {
    return (a - o).x() * (b - o).y() - (a - o).y() * (b - o).x();
  };
  std::vector<Vector2> hull(2 * points.size());
  std::size_t k = 0;
  for (const Vector2& p : points) {  // the lower chain, left to right
    while (k >= 2 && cross(hull[k - 2], hull[k - 1], p) <= 0) --k;
    hull[k++] = p;
  }
  const std::size_t lower = k + 1;
  for (std::size_t i = points.size() - 1; i-- > 0;) {  // the upper chain, right to left
    while (k >= lower && cross(hull[k - 2], hull[k - 1], points[i]) <= 0) --k;
    hull[k++] = points[i];
  }
  hull.resize(k - 1);  // its last point is the first
  return hull;
}

double relative_change(const Eigen::Ref<const Vector>& frame, const Eigen::Ref<const Vector>& reference,
                       Eigen::Ref<Vector> change, const ReadingScreen& screen) {
  double norm2 = 0;
  for (Index m = 0; m < frame.size(); ++m) {
    if (screen.is_dropped(m)) change(m) = 0;
    else if (screen.usable(frame(m), reference(m))) change(m) = std::log(frame(m) / reference(m));
    else change(m) = std::numeric_limits<double>::quiet_NaN();
    if (std::isfinite(change(m))) norm2 += change(m) * change(m);
  }
  const double norm = std::sqrt(norm2);
  if (!(norm > 0)) return 0;
  change /= norm;
  return norm;
}

}  // namespace emit
