#include "emit/calibrate/press_response_fit.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include <Eigen/Cholesky>
#include <Eigen/LU>

#include "emit/core/errors.hpp"
#include "emit/frame/press_locator.hpp"

namespace emit {

void PressResponseFitOptions::validate() const {
  if (degrees.empty()) throw InvalidInput("press response: degrees: give at least one");
  for (const int d : degrees)
    if (d < 0 || d > 12) throw InvalidInput("press response: degrees: each must be 0 to 12, got " + std::to_string(d));
  if (shrinkages.empty()) throw InvalidInput("press response: shrinkages: give at least one");
  for (const double rho : shrinkages)
    if (!(rho >= 0 && rho <= 1))
      throw InvalidInput("press response: shrinkages: each must be in [0, 1], got " + std::to_string(rho));
  if (folds < 2) throw InvalidInput("press response: folds must be at least 2, got " + std::to_string(folds));
  if (grid_divisions < 2) throw InvalidInput("press response: grid_divisions must be at least 2");
  for (const double l : kernel_lengths_mm)
    if (!(l > 0)) throw InvalidInput("press response: kernel lengths: each must be positive, got " + std::to_string(l));
  if (!kernel_lengths_mm.empty() && kernel_smoothings.empty())
    throw InvalidInput("press response: kernel smoothings: give at least one for the kernel lengths");
  for (const double l : kernel_smoothings)
    if (!(l > 0))
      throw InvalidInput("press response: kernel smoothings: each must be positive, got " + std::to_string(l));
  if (drift_rates.empty()) throw InvalidInput("press response: drift rates: give at least one (0: none)");
  for (const double f : drift_rates)
    if (!(f >= 0 && f < 1))
      throw InvalidInput("press response: drift rates: each must be in [0, 1), got " + std::to_string(f));
}

namespace {

/// The response of one candidate fitted to the presses `rows`, with the region given.
PressResponse fit_one(const Matrix& changes, const std::vector<Vector2>& positions_mm, const std::vector<Index>& rows,
                      const PressResponseCandidate& candidate, const PressResponse& frame_of_reference) {
  PressResponse r = frame_of_reference;
  r.degree = candidate.degree;
  const double shrinkage = candidate.shrinkage;
  if (candidate.kernel_length_mm > 0) {
    // The bumps reach the region's margin: centres within the presses' reach and a quarter width.
    r.kernel_length_mm = candidate.kernel_length_mm;
    r.centres_mm = hexagonal_lattice(r.center_mm, r.scale_mm + r.kernel_length_mm / 4, r.kernel_length_mm);
  }
  const Index n = static_cast<Index>(rows.size()), B = r.basis_size(), M = changes.cols();
  Matrix basis(B, n), data(n, M);  // column i: press i's b(p)
  for (Index i = 0; i < n; ++i) {
    const Index row = rows[static_cast<std::size_t>(i)];
    r.basis_at(positions_mm[static_cast<std::size_t>(row)], basis.col(i));
    data.row(i) = changes.row(row);
  }
  Matrix normal = basis * basis.transpose();
  normal.diagonal().array() += 1e-6 * static_cast<double>(n);
  if (const auto C = static_cast<Index>(r.centres_mm.size()); C > 0) {
    Matrix kernel(C, C);  // the bumps' prior: λ n aᵀKa
    for (Index i = 0; i < C; ++i)
      for (Index j = 0; j < C; ++j)
        kernel(i, j) = std::exp(
            -0.5 *
            (r.centres_mm[static_cast<std::size_t>(i)] - r.centres_mm[static_cast<std::size_t>(j)]).squaredNorm() /
            (r.kernel_length_mm * r.kernel_length_mm));
    normal.bottomRightCorner(C, C) += candidate.smoothing * static_cast<double>(n) * kernel;
  }
  r.coefficients = normal.ldlt().solve(basis * data);
  const Matrix residual = data - basis.transpose() * r.coefficients;
  Matrix covariance = residual.transpose() * residual / static_cast<double>(n);
  const Vector diagonal = covariance.diagonal();
  covariance *= 1 - shrinkage;
  covariance.diagonal() += shrinkage * diagonal;
  // A floor under the diagonal keeps Λ finite for a reading the model fits exactly.
  covariance.diagonal().array() += 1e-12 + 1e-9 * diagonal.mean();
  r.precision = covariance.llt().solve(Matrix::Identity(M, M));
  return r;
}

/// The calibration presses' hull grown by half their typical spacing, √(area / n) / 2: presses
/// sample the skin's pressed area that finely, so it reaches about that far past their hull. Each
/// edge moves out by the margin m, so each corner moves by m (n₁ + n₂)/(1 + n₁·n₂), n₁ and n₂ the
/// outward normals of its edges (the offset of a convex polygon with mitred corners).
std::vector<Vector2> grown_region(const std::vector<Vector2>& hull, double presses) {
  double twice_area = 0;
  for (std::size_t i = 0; i < hull.size(); ++i) {
    const Vector2& a = hull[i];
    const Vector2& b = hull[(i + 1) % hull.size()];
    twice_area += a.x() * b.y() - a.y() * b.x();
  }
  const double margin = 0.5 * std::sqrt(0.5 * twice_area / presses);
  const auto outward = [&](std::size_t i) {  // of edge i → i + 1, counter-clockwise
    const Vector2 edge = (hull[(i + 1) % hull.size()] - hull[i]).normalized();
    return Vector2(edge.y(), -edge.x());
  };
  std::vector<Vector2> grown(hull.size());
  for (std::size_t i = 0; i < hull.size(); ++i) {
    const Vector2 before = outward((i + hull.size() - 1) % hull.size()), after = outward(i);
    grown[i] = hull[i] + margin * (before + after) / (1 + before.dot(after));
  }
  return grown;
}

/// Fills the masked (NaN) entries of `changes` from the model at each press's place, the model
/// fitted to the presses with what is known, twice; each filled row renormalised. \return the
/// number of rows filled.
Index fill_masked(Matrix& changes, const std::vector<Vector2>& positions_mm, int degree, const PressResponse& base) {
  const PressResponseCandidate plain{degree, 1.0, 0, 0, 0};
  const Matrix measured = changes;
  const Eigen::Array<bool, Eigen::Dynamic, Eigen::Dynamic> masked = measured.array().isNaN();
  std::vector<Index> rows, all(static_cast<std::size_t>(changes.rows()));
  for (Index i = 0; i < changes.rows(); ++i) {
    all[static_cast<std::size_t>(i)] = i;
    if (masked.row(i).any()) rows.push_back(i);
  }
  if (rows.empty()) return 0;
  changes = masked.select(0.0, measured.array()).matrix();
  Vector basis(response_basis_size(degree)), model(changes.cols());
  for (int round = 0; round < 2; ++round) {
    const PressResponse r = fit_one(changes, positions_mm, all, plain, base);
    for (const Index i : rows) {
      r.basis_at(positions_mm[static_cast<std::size_t>(i)], basis);
      model.noalias() = r.coefficients.transpose() * basis;
      double dm = 0, mm = 0;  // the press's amplitude, from the readings used
      for (Index m = 0; m < changes.cols(); ++m)
        if (!masked(i, m)) dm += measured(i, m) * model(m), mm += model(m) * model(m);
      const double a = mm > 0 ? dm / mm : 0;
      for (Index m = 0; m < changes.cols(); ++m) changes(i, m) = masked(i, m) ? a * model(m) : measured(i, m);
      if (const double norm = changes.row(i).norm(); norm > 0) changes.row(i) /= norm;
    }
  }
  return static_cast<Index>(rows.size());
}

/// A located press's miss: its distance from the true place (2 s for a press not found) and the
/// share of its change the model left unexplained.
Vector2 miss_of(const LocatedPress& located, const Vector2& truth_mm, double scale_mm) {
  return {located.found ? (located.position_mm - truth_mm).norm() : 2 * scale_mm, 1 - located.explained};
}

/// Presses [first, n) located in order by `response` with the drift at `rate`: their misses.
std::vector<Vector2> misses_in_order(const PressResponse& response, double rate, int grid_divisions,
                                     const Matrix& measured, const std::vector<Vector2>& positions_mm, Index first) {
  PressLocator locator(response, PressLocatorOptions{grid_divisions, rate, {}, -1});
  std::vector<Vector2> misses;
  for (Index i = first; i < measured.rows(); ++i)
    misses.push_back(miss_of(locator.locate_change(measured.row(i).transpose()),
                             positions_mm[static_cast<std::size_t>(i)], response.scale_mm));
  return misses;
}

/// The fastest rate whose paired excess error over the best rate's is within one standard error
/// (fit_press_response's drift rate); errors[r]: rate r's misses.
double fastest_within_noise(const std::vector<double>& rates, const std::vector<std::vector<Vector2>>& errors,
                            std::vector<double>& means) {
  means.clear();
  for (const auto& e : errors) {
    double sum = 0;
    for (const Vector2& v : e) sum += v.x();
    means.push_back(sum / static_cast<double>(e.size()));
  }
  const auto best = static_cast<std::size_t>(std::min_element(means.begin(), means.end()) - means.begin());
  double kept = rates[best];
  for (std::size_t r = 0; r < errors.size(); ++r) {
    const auto m = static_cast<double>(errors[r].size());
    double mean = 0, square = 0;
    for (std::size_t i = 0; i < errors[r].size(); ++i) {
      const double excess = errors[r][i].x() - errors[best][i].x();
      mean += excess / m, square += excess * excess;
    }
    const double standard_error = std::sqrt(std::max(square - m * mean * mean, 0.0) / std::max(m - 1, 1.0) / m);
    if (mean <= standard_error) kept = std::max(kept, rates[r]);
  }
  return kept;
}

/// The least k that puts 68 % of the ratios error / √(unexplained + u₀) within k and 95 % within 2k,
/// by their order statistics (split conformal: the ⌈(m + 1) q⌉-th smallest of m covers a new
/// exchangeable one with probability q or more).
double conformal_scale(const std::vector<Vector2>& misses, double floor) {
  std::vector<double> ratios;
  ratios.reserve(misses.size());
  for (const Vector2& v : misses) ratios.push_back(v.x() / std::sqrt(v.y() + floor));
  std::sort(ratios.begin(), ratios.end());
  const auto order_statistic = [&](double q) {
    const auto k = static_cast<std::size_t>(std::ceil((static_cast<double>(ratios.size()) + 1) * q));
    return ratios[std::min(k, ratios.size()) - 1];
  };
  return std::max(order_statistic(0.68), order_statistic(0.95) / 2);
}

}  // namespace

PressResponseFit fit_press_response(const Matrix& changes, const std::vector<Vector2>& positions_mm,
                                    const PressResponseFitOptions& options, const Progress& progress) {
  options.validate();
  const Index n = changes.rows();
  if (static_cast<std::size_t>(n) != positions_mm.size())
    throw InvalidInput("press response: " + std::to_string(n) + " changes for " + std::to_string(positions_mm.size()) +
                       " positions");
  if (n < 2 * static_cast<Index>(options.folds))
    throw InvalidInput("press response: " + std::to_string(n) + " calibration presses; at least " +
                       std::to_string(2 * options.folds) + " are needed (" + std::to_string(options.folds) +
                       "-fold cross-validation)");
  // The chart: centred on the presses, scaled to their reach.
  PressResponse base;
  for (const Vector2& p : positions_mm) base.center_mm += p / static_cast<double>(n);
  double reach = 0;
  for (const Vector2& p : positions_mm) reach = std::max(reach, (p - base.center_mm).norm());
  base.scale_mm = reach > 0 ? reach : 1;
  base.region_mm = convex_hull(positions_mm);
  if (base.region_mm.size() < 3) throw InvalidInput("press response: the calibration presses lie on a line");
  base.region_mm = grown_region(base.region_mm, static_cast<double>(n));

  PressResponseFit fit;
  const Matrix& measured = changes;  // NaN where masked: the cross-validation locates these
  Matrix filled = changes;
  fit.filled_presses = fill_masked(filled, positions_mm, options.degrees.front(), base);

  std::vector<PressResponseCandidate> tried;
  for (const int degree : options.degrees)
    for (const double shrinkage : options.shrinkages) tried.push_back({degree, shrinkage, 0, 0, 0});
  for (const double length : options.kernel_lengths_mm)
    for (const double smoothing : options.kernel_smoothings)
      for (const double shrinkage : options.shrinkages) tried.push_back({1, shrinkage, length, smoothing, 0});
  const auto total = static_cast<long>(tried.size());
  long done = 0;
  // Per candidate: each press's error and 1 − explained when held out (for the σ's scale).
  std::vector<std::vector<Vector2>> held_out_misses;
  for (PressResponseCandidate& candidate : tried) {
    progress.step("cross-validating press response", done++, total);
    double error = 0;
    std::vector<Vector2>& misses = held_out_misses.emplace_back();
    for (int fold = 0; fold < options.folds; ++fold) {
      std::vector<Index> train, test;
      for (Index i = 0; i < n; ++i) (i % options.folds == fold ? test : train).push_back(i);
      PressLocator locator(fit_one(filled, positions_mm, train, candidate, base), options.grid_divisions);
      for (const Index i : test) {
        misses.push_back(miss_of(locator.locate_change(measured.row(i).transpose()),
                                 positions_mm[static_cast<std::size_t>(i)], base.scale_mm));
        error += misses.back().x();
      }
    }
    candidate.cross_validated_mm = error / static_cast<double>(n);
    fit.candidates.push_back(candidate);
  }
  progress.step("cross-validating press response", total, total);
  const auto kept = std::min_element(fit.candidates.begin(), fit.candidates.end(), [](const auto& a, const auto& b) {
    return a.cross_validated_mm < b.cross_validated_mm;
  });
  std::vector<Index> all(static_cast<std::size_t>(n));
  for (Index i = 0; i < n; ++i) all[static_cast<std::size_t>(i)] = i;
  fit.response = fit_one(filled, positions_mm, all, *kept, base);
  fit.kept = *kept;

  // The drift rate, as a live session would meet it: the first half calibrates, the second is
  // located in order. Half a calibration is too short for most drift to show, so the fastest
  // rate whose cost there is within the noise (its paired excess over the best rate within one
  // standard error) is kept: tracking costs little on a skin that holds still, and gains much on
  // one that drifts.
  std::vector<Index> first(all.begin(), all.begin() + n / 2);
  const PressResponse half = fit_one(filled, positions_mm, first, *kept, base);
  std::vector<std::vector<Vector2>> by_rate;
  for (const double rate : options.drift_rates)
    by_rate.push_back(misses_in_order(half, rate, options.grid_divisions, measured, positions_mm, n / 2));
  fit.drift_rate = fastest_within_noise(options.drift_rates, by_rate, fit.drift_errors_mm);

  // The σ's scale (frame/press_locator.hpp, "How sure"): u₀ the median 1 − explained of the kept
  // candidate's cross-validation; k by conformal_scale on presses a model did not see, the larger
  // of two sets' k: the kept candidate's cross-validation (models of nine tenths of the presses,
  // as sure as the final one) and the second half located in order with the rate kept (a model
  // of half the presses, but meeting the drift).
  const std::vector<Vector2>& validated = held_out_misses[static_cast<std::size_t>(kept - fit.candidates.begin())];
  std::vector<double> unexplained;
  unexplained.reserve(validated.size());
  for (const Vector2& v : validated) unexplained.push_back(v.y());
  std::nth_element(unexplained.begin(), unexplained.begin() + static_cast<std::ptrdiff_t>(unexplained.size() / 2),
                   unexplained.end());
  fit.response.unexplained_floor = std::max(unexplained[unexplained.size() / 2], 1e-9);
  const auto rate = static_cast<std::size_t>(
      std::find(options.drift_rates.begin(), options.drift_rates.end(), fit.drift_rate) - options.drift_rates.begin());
  fit.response.error_scale_mm = std::max(conformal_scale(by_rate[rate], fit.response.unexplained_floor),
                                         conformal_scale(validated, fit.response.unexplained_floor));
  return fit;
}

}  // namespace emit
