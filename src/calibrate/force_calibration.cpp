#include "emit/calibrate/force_calibration.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include <ceres/ceres.h>

#include "emit/core/errors.hpp"

namespace emit {

namespace {

/// ln F̂ − ln F of one sample in the positive parameterisation (b1, c, b3):
/// base = b1·(x − x_min) + c, x = 1/I, ln F̂ = b3·ln(base).
struct LogForceResidual {
  double x, x_min, log_force;
  template <class T>
  bool operator()(const T* b1, const T* c, const T* b3, T* residual) const {
    residual[0] = b3[0] * ceres::log(b1[0] * (x - x_min) + c[0]) - log_force;
    return true;
  }
};

void check_samples(const std::vector<ForceSample>& samples) {
  if (samples.size() < 4)
    throw InvalidInput("force calibration needs at least 4 presses with a contact, got " +
                       std::to_string(samples.size()));
  double lowest = samples[0].true_force_N, highest = lowest;
  for (std::size_t i = 0; i < samples.size(); ++i) {
    const ForceSample& s = samples[i];
    if (!(s.integral_V_mm2 > 0 && std::isfinite(s.integral_V_mm2)))
      throw InvalidInput("force calibration press " + std::to_string(i) + ": its image's integral is not positive");
    if (!(s.true_force_N > 0 && std::isfinite(s.true_force_N)))
      throw InvalidInput("force calibration press " + std::to_string(i) + " has no force");
    lowest = std::min(lowest, s.true_force_N);
    highest = std::max(highest, s.true_force_N);
  }
  if (!(highest > lowest * 1.01)) throw InvalidInput("force calibration needs presses of different forces");
}

}  // namespace

ForceFit fit_image_force_law(const std::vector<ForceSample>& samples) {
  check_samples(samples);
  const auto n = static_cast<double>(samples.size());
  double x_min = std::numeric_limits<double>::infinity(), radius_mm = 0;
  for (const ForceSample& s : samples) x_min = std::min(x_min, 1.0 / s.integral_V_mm2), radius_mm += s.radius_mm;
  // Start from F = k·I^s fitted in log space (b2 = 0), which the law contains: b3 = −s, b1 = k^(1/b3).
  double sx = 0, sy = 0, sxx = 0, sxy = 0;
  for (const ForceSample& s : samples) {
    const double x = std::log(s.integral_V_mm2), y = std::log(s.true_force_N);
    sx += x, sy += y, sxx += x * x, sxy += x * y;
  }
  const double denominator = n * sxx - sx * sx;
  const double slope = denominator > 0 ? (n * sxy - sx * sy) / denominator : 1.0;
  const double intercept = (sy - slope * sx) / n;
  double b3 = slope > 0.05 ? -slope : -1.0;
  double b1 = std::exp(intercept / b3);
  double c = b1 * x_min;

  ceres::Problem problem;
  for (const ForceSample& s : samples)
    problem.AddResidualBlock(new ceres::AutoDiffCostFunction<LogForceResidual, 1, 1, 1, 1>(
                                 new LogForceResidual{1.0 / s.integral_V_mm2, x_min, std::log(s.true_force_N)}),
                             nullptr, &b1, &c, &b3);
  problem.SetParameterLowerBound(&b1, 0, 0.0);
  problem.SetParameterLowerBound(&c, 0, 1e-12 * c);
  problem.SetParameterUpperBound(&b3, 0, -1e-3);  // the force grows with the image
  ceres::Solver::Options options;
  options.linear_solver_type = ceres::DENSE_QR;
  options.max_num_iterations = 200;
  options.function_tolerance = 1e-14;
  options.parameter_tolerance = 1e-14;
  options.logging_type = ceres::SILENT;
  ceres::Solver::Summary summary;
  ceres::Solve(options, &problem, &summary);
  if (!summary.IsSolutionUsable()) throw SolverError("force calibration did not converge: " + summary.message);

  ForceFit fit;
  fit.law.b1_V_mm2 = b1;
  fit.law.b2 = c - b1 * x_min;
  fit.law.b3 = b3;
  fit.law.indenter_radius_mm = radius_mm / n;
  double squares = 0;
  for (const ForceSample& s : samples) {
    const double ratio = fit.law.force_N(s.integral_V_mm2) / s.true_force_N;
    fit.relative_errors.push_back(ratio - 1);
    fit.mean_abs_relative_error += std::abs(ratio - 1) / n;
    squares += std::log(ratio) * std::log(ratio);
  }
  fit.law.log_std = std::sqrt(squares / std::max(1.0, n - 3));
  return fit;
}

}  // namespace emit
