#include "emit/frame/press_locator.hpp"

#include <cmath>
#include <string>
#include <utility>
#include <vector>

#include "emit/core/errors.hpp"
#include "emit/core/small_cholesky.hpp"

namespace emit {

void PressLocatorOptions::validate() const {
  if (grid_divisions < 2) throw InvalidInput("press locator: the grid needs at least 2 divisions");
  if (!(drift_rate >= 0 && drift_rate < 1))
    throw InvalidInput("press locator: drift rate: must be in [0, 1), got " + std::to_string(drift_rate));
  if (max_masked < -1) throw InvalidInput("press locator: max masked: must be −1 (a quarter) or more");
}

PressLocator::PressLocator(PressResponse response, int grid_divisions)
    : PressLocator(std::move(response), PressLocatorOptions{grid_divisions, 0, {}, -1}) {}

PressLocator::PressLocator(PressResponse response, PressLocatorOptions options)
    : response_(std::move(response)), options_(std::move(options)) {
  options_.validate();
  if (response_.region_mm.size() < 3) throw InvalidInput("press locator: the press response has no region to search");
  const Index M = response_.readings(), B = response_.basis_size();
  if (!options_.screen.dropped.empty() && static_cast<Index>(options_.screen.dropped.size()) != M)
    throw InvalidInput("press locator: a screen of " + std::to_string(options_.screen.dropped.size()) +
                       " channels for a response of " + std::to_string(M) + " readings");
  Vector2 low = response_.region_mm.front(), high = low;
  for (const Vector2& p : response_.region_mm) low = low.cwiseMin(p), high = high.cwiseMax(p);
  grid_step_mm_ = (high - low).maxCoeff() / options_.grid_divisions;
  if (!(grid_step_mm_ > 0)) throw InvalidInput("press locator: the press response's region has no extent");
  std::vector<Vector2> points;
  const Eigen::Array2i steps = ((high - low) / grid_step_mm_).array().floor().cast<int>();
  for (int i = 0; i <= steps.x(); ++i)
    for (int j = 0; j <= steps.y(); ++j)
      if (const Vector2 p = low + grid_step_mm_ * Vector2(i, j); response_.in_region(p)) points.push_back(p);
  const auto G = static_cast<Index>(points.size());
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
  max_masked_ = options_.max_masked < 0 ? M / 4 : std::min(options_.max_masked, M);
  for (Vector* v : {&change_, &used_change_, &weighted_change_, &model_, &drift_}) v->setZero(M);
  for (Vector* v : {&projected_change_, &basis_, &gram_basis_}) v->resize(B);
  grid_scores_.resize(G);
  bad_.resize(M);
  masked_block_.resize(max_masked_, max_masked_);
  masked_z_.resize(B, max_masked_);
  masked_grid_.resize(G, max_masked_);
  masked_gram_.resize(B, B);
  masked_y_.resize(max_masked_);
  masked_norm2_.resize(G);
}

double PressLocator::score_at(const Vector2& p_mm) {
  response_.basis_at(p_mm, basis_);
  gram_basis_.noalias() = *gram_now_ * basis_;
  const double dm = basis_.dot(projected_change_);  // dᵀΛm
  const double mm = basis_.dot(gram_basis_);        // mᵀΛm
  return mm > 0 && dm > 0 ? dm * dm / mm : -1;
}

LocatedPress PressLocator::locate(const Eigen::Ref<const Vector>& frame, const Eigen::Ref<const Vector>& reference) {
  const Index M = response_.readings();
  if (frame.size() != M || reference.size() != M)
    throw InvalidInput("press locator: a frame of " + std::to_string(frame.size()) + " values and a reference of " +
                       std::to_string(reference.size()) + " for a response of " + std::to_string(M) + " readings");
  const double size = relative_change(frame, reference, change_, options_.screen);
  if (!(size > 0)) return {};
  LocatedPress located = locate_normalised();
  Index used = 0;
  for (Index m = 0; m < M; ++m) used += std::isfinite(change_(m)) && !options_.screen.is_dropped(m) ? 1 : 0;
  located.relative_change_rms = size / std::sqrt(static_cast<double>(std::max<Index>(used, 1)));
  return located;
}

LocatedPress PressLocator::locate_change(const Eigen::Ref<const Vector>& change) {
  if (change.size() != response_.readings())
    throw InvalidInput("press locator: a change of " + std::to_string(change.size()) + " values for a response of " +
                       std::to_string(response_.readings()) + " readings");
  change_ = change;
  return locate_normalised();
}

double PressLocator::marginalise(Index k) {
  const Matrix& precision = response_.precision;
  // Λ_𝓑𝓑 = LLᵀ (core/small_cholesky.hpp: Eigen's would allocate per frame).
  auto L = masked_block_.topLeftCorner(k, k);
  small_cholesky(
      k, [&](Index i, Index j) { return precision(bad_(i), bad_(j)); }, L);
  // y = (Λd)_𝓑 (d is 0 on 𝓑), t = Λ_𝓑𝓑⁻¹ y; Λ'd = Λd − Λ_{·𝓑} t.
  auto t = masked_y_.head(k);
  for (Index i = 0; i < k; ++i) t(i) = weighted_change_(bad_(i));
  small_cholesky_solve(L, t);
  for (Index i = 0; i < k; ++i) weighted_change_ -= t(i) * precision.col(bad_(i));
  // Z = CL⁻ᵀ, C = WΛ_{·𝓑}: column j of Z from C's column j and Z's earlier columns.
  for (Index j = 0; j < k; ++j) {
    masked_z_.col(j).noalias() = response_.coefficients * precision.col(bad_(j));
    for (Index l = 0; l < j; ++l) masked_z_.col(j) -= L(j, l) * masked_z_.col(l);
    masked_z_.col(j) /= L(j, j);
  }
  masked_gram_ = gram_;
  masked_norm2_ = grid_norm2_;
  for (Index j = 0; j < k; ++j) {
    masked_gram_.noalias() -= masked_z_.col(j) * masked_z_.col(j).transpose();
    masked_grid_.col(j).noalias() = grid_basis_ * masked_z_.col(j);
    masked_norm2_.array() -= masked_grid_.col(j).array().square();
  }
  gram_now_ = &masked_gram_;
  grid_norm2_now_ = &masked_norm2_;
  return used_change_.dot(weighted_change_);
}

void PressLocator::learn_drift(const Vector2& p_mm) {
  response_.basis_at(p_mm, basis_);
  model_.noalias() = response_.coefficients.transpose() * basis_;
  double dm = 0, mm = 0;
  for (Index m = 0; m < model_.size(); ++m)
    if (std::isfinite(change_(m))) dm += change_(m) * model_(m), mm += model_(m) * model_(m);
  if (!(mm > 0)) return;
  const double a = dm / mm, f = options_.drift_rate;
  for (Index m = 0; m < model_.size(); ++m)
    if (std::isfinite(change_(m))) drift_(m) = (1 - f) * drift_(m) + f * (change_(m) - a * model_(m));
}

LocatedPress PressLocator::locate_normalised() {
  LocatedPress located;
  // The masked readings: NaN in the change.
  Index k = 0;
  for (Index m = 0; m < change_.size(); ++m) {
    const bool masked = !std::isfinite(change_(m));
    if (masked && k < max_masked_) bad_(k) = m;
    k += masked ? 1 : 0;
    used_change_(m) = masked ? 0 : change_(m) - drift_(m);
  }
  located.masked = static_cast<int>(k);
  if (k > max_masked_ || !(used_change_.squaredNorm() > 0)) return located;
  weighted_change_.noalias() = response_.precision * used_change_;
  gram_now_ = &gram_;
  grid_norm2_now_ = &grid_norm2_;
  const double dd = k > 0 ? marginalise(k) : used_change_.dot(weighted_change_);
  projected_change_.noalias() = response_.coefficients * weighted_change_;
  grid_scores_.noalias() = grid_basis_ * projected_change_;
  const Vector& norm2 = *grid_norm2_now_;
  Index best = -1;
  double best_score = 0;
  for (Index g = 0; g < grid_scores_.size(); ++g) {
    const double dm = grid_scores_(g);
    if (dm > 0 && norm2(g) > 0 && dm * dm / norm2(g) > best_score) {
      best_score = dm * dm / norm2(g);
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
  located.explained = dd > 0 ? std::min(1.0, best_score / dd) : 0;
  located.std_mm = response_.error_scale_mm * std::sqrt(1 - located.explained + response_.unexplained_floor);
  located.x_std_mm = located.y_std_mm = located.std_mm / std::sqrt(2.0);
  if (options_.drift_rate > 0) learn_drift(p);
  return located;
}

}  // namespace emit
