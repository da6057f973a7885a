#include "emit/frame/press_locator.hpp"

#include <cmath>
#include <string>
#include <vector>

#include "emit/core/errors.hpp"

namespace emit {

PressLocator::PressLocator(PressResponse response, int grid_divisions) : response_(std::move(response)) {
  if (grid_divisions < 2) throw InvalidInput("press locator: the grid needs at least 2 divisions");
  if (response_.region_mm.size() < 3) throw InvalidInput("press locator: the press response has no region to search");
  Vector2 low = response_.region_mm.front(), high = low;
  for (const Vector2& p : response_.region_mm) low = low.cwiseMin(p), high = high.cwiseMax(p);
  grid_step_mm_ = (high - low).maxCoeff() / grid_divisions;
  if (!(grid_step_mm_ > 0)) throw InvalidInput("press locator: the press response's region has no extent");
  std::vector<Vector2> points;
  const Eigen::Array2i steps = ((high - low) / grid_step_mm_).array().floor().cast<int>();
  for (int i = 0; i <= steps.x(); ++i)
    for (int j = 0; j <= steps.y(); ++j)
      if (const Vector2 p = low + grid_step_mm_ * Vector2(i, j); response_.in_region(p)) points.push_back(p);
  const Index M = response_.readings(), G = static_cast<Index>(points.size());
  const Index B = response_basis_size(response_.degree);
  grid_mm_.resize(2, G);
  Matrix basis(B, G);
  for (Index g = 0; g < G; ++g) {
    grid_mm_.col(g) = points[static_cast<std::size_t>(g)];
    response_.basis_at(points[static_cast<std::size_t>(g)], basis.col(g));
  }
  // In the basis' coordinates: m(p)ᵀΛm(p) = b(p)ᵀ (WΛWᵀ) b(p) and dᵀΛm(p) = (WΛd)ᵀ b(p).
  gram_ = response_.coefficients * response_.precision * response_.coefficients.transpose();
  grid_basis_ = basis.transpose();
  grid_norm2_ = ((grid_basis_ * gram_).array() * grid_basis_.array()).rowwise().sum();
  change_.resize(M);
  weighted_change_.resize(M);
  projected_change_.resize(B);
  grid_scores_.resize(G);
  basis_.resize(B);
  gram_basis_.resize(B);
}

double PressLocator::score_at(const Vector2& p_mm) {
  response_.basis_at(p_mm, basis_);
  gram_basis_.noalias() = gram_ * basis_;
  const double dm = basis_.dot(projected_change_);  // dᵀΛm
  const double mm = basis_.dot(gram_basis_);        // mᵀΛm
  return mm > 0 && dm > 0 ? dm * dm / mm : -1;
}

LocatedPress PressLocator::locate(const Eigen::Ref<const Vector>& frame, const Eigen::Ref<const Vector>& reference) {
  const Index M = response_.readings();
  if (frame.size() != M || reference.size() != M)
    throw InvalidInput("press locator: a frame of " + std::to_string(frame.size()) + " values and a reference of " +
                       std::to_string(reference.size()) + " for a response of " + std::to_string(M) + " readings");
  const double size = relative_change(frame, reference, change_);
  if (!(size > 0)) return {};
  LocatedPress located = locate_normalised();
  located.relative_change_rms = size / std::sqrt(static_cast<double>(M));
  return located;
}

LocatedPress PressLocator::locate_change(const Eigen::Ref<const Vector>& change) {
  if (change.size() != response_.readings())
    throw InvalidInput("press locator: a change of " + std::to_string(change.size()) + " values for a response of " +
                       std::to_string(response_.readings()) + " readings");
  change_ = change;
  return locate_normalised();
}

LocatedPress PressLocator::locate_normalised() {
  LocatedPress located;
  weighted_change_.noalias() = response_.precision * change_;
  projected_change_.noalias() = response_.coefficients * weighted_change_;
  grid_scores_.noalias() = grid_basis_ * projected_change_;
  Index best = -1;
  double best_score = 0;
  for (Index g = 0; g < grid_scores_.size(); ++g) {
    const double dm = grid_scores_(g);
    if (dm > 0 && grid_norm2_(g) > 0 && dm * dm / grid_norm2_(g) > best_score) {
      best_score = dm * dm / grid_norm2_(g);
      best = g;
    }
  }
  if (best < 0) return located;
  // Refine: a 5 × 5 patch about the best point, its spacing halved each round, within the region.
  Vector2 p = grid_mm_.col(best);
  best_score = score_at(p);
  double step = grid_step_mm_ / 2;
  for (int round = 0; round < 5; ++round, step /= 2) {
    const Vector2 centre = p;
    for (int i = -2; i <= 2; ++i)
      for (int j = -2; j <= 2; ++j) {
        const Vector2 q = centre + Vector2(i * step, j * step);
        if ((i == 0 && j == 0) || !response_.in_region(q)) continue;
        if (const double s = score_at(q); s > best_score) best_score = s, p = q;
      }
  }
  located.found = true;
  located.position_mm = p;
  const double dd = change_.dot(weighted_change_);
  located.explained = dd > 0 ? best_score / dd : 0;
  return located;
}

}  // namespace emit
