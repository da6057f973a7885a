#include "emit/calibrate/pressure_calibration.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include <ceres/ceres.h>

#include "emit/core/errors.hpp"

namespace emit {

PressureSample pressure_sample(const Reconstructor& reconstructor, double threshold_fraction,
                               double true_pressure_N_per_mm2) {
  PressureSample sample;
  sample.true_pressure_N_per_mm2 = true_pressure_N_per_mm2;
  const Vector& dphi = reconstructor.image();
  const double threshold = threshold_fraction * dphi.maxCoeff();
  for (Index k = 0; k < dphi.size(); ++k)
    if (dphi[k] > 0 && dphi[k] >= threshold) {
      sample.dphi_V.push_back(dphi[k]);
      sample.area_mm2.push_back(reconstructor.mesh().triangle_area_mm2(k));
    }
  return sample;
}

double predicted_pressure(const LinearCalibration& calibration, const PressureSample& sample) {
  double force = 0, area = 0;
  for (std::size_t k = 0; k < sample.dphi_V.size(); ++k) {
    force += sample.area_mm2[k] * calibration.pressure_N_per_mm2(sample.dphi_V[k]);
    area += sample.area_mm2[k];
  }
  return area > 0 ? force / area : 0.0;
}

namespace {

/// Residual of one sample in the positive parameterisation (a1, b, a3):
/// base_k = a1·(x_k − x_min) + b, x = 1/δφ; mean pressure Σ A_k base_k^a3 / Σ A_k − P_true.
struct MeanPressureResidual {
  const PressureSample& sample;
  double x_min;
  template <class T>
  bool operator()(const T* a1, const T* b, const T* a3, T* residual) const {
    T force(0.0);
    double area = 0;
    for (std::size_t k = 0; k < sample.dphi_V.size(); ++k) {
      const T base = a1[0] * (1.0 / sample.dphi_V[k] - x_min) + b[0];
      force += sample.area_mm2[k] * ceres::pow(base, a3[0]);
      area += sample.area_mm2[k];
    }
    residual[0] = force / area - sample.true_pressure_N_per_mm2;
    return true;
  }
};

/// Mean potential of a sample (area-weighted), for the starting guess.
double mean_dphi(const PressureSample& s) {
  double sum = 0, area = 0;
  for (std::size_t k = 0; k < s.dphi_V.size(); ++k) sum += s.area_mm2[k] * s.dphi_V[k], area += s.area_mm2[k];
  return sum / area;
}

void check_samples(const std::vector<PressureSample>& samples) {
  if (samples.size() < 3)
    throw InvalidInput("calibration needs at least 3 presses, got " + std::to_string(samples.size()));
  double lowest = samples[0].true_pressure_N_per_mm2, highest = lowest;
  for (std::size_t i = 0; i < samples.size(); ++i) {
    if (samples[i].dphi_V.empty())
      throw InvalidInput("calibration press " + std::to_string(i) + " shows no contact in its frame");
    if (!(samples[i].true_pressure_N_per_mm2 > 0))
      throw InvalidInput("calibration press " + std::to_string(i) + " has no pressure");
    lowest = std::min(lowest, samples[i].true_pressure_N_per_mm2);
    highest = std::max(highest, samples[i].true_pressure_N_per_mm2);
  }
  if (!(highest > lowest * 1.01)) throw InvalidInput("calibration needs presses of different pressures");
}

}  // namespace

PressureFit fit_pressure_calibration(const std::vector<PressureSample>& samples) {
  check_samples(samples);
  double x_min = std::numeric_limits<double>::infinity();
  for (const auto& s : samples)
    for (double d : s.dphi_V) x_min = std::min(x_min, 1.0 / d);
  // Start from P = c·δφ^s fitted in log space (a2 = 0), which eq. 8 contains: a3 = −s, a1 = c^(1/a3).
  double sx = 0, sy = 0, sxx = 0, sxy = 0;
  for (const auto& s : samples) {
    const double x = std::log(mean_dphi(s)), y = std::log(s.true_pressure_N_per_mm2);
    sx += x, sy += y, sxx += x * x, sxy += x * y;
  }
  const auto n = static_cast<double>(samples.size());
  const double slope = (n * sxy - sx * sy) / (n * sxx - sx * sx);
  const double intercept = (sy - slope * sx) / n;
  double a3 = slope > 0.05 ? -slope : -1.0;
  double a1 = std::exp(intercept / a3);
  double b = a1 * x_min;

  ceres::Problem problem;
  for (const auto& s : samples)
    problem.AddResidualBlock(new ceres::AutoDiffCostFunction<MeanPressureResidual, 1, 1, 1, 1>(
                                 new MeanPressureResidual{s, x_min}),
                             nullptr, &a1, &b, &a3);
  problem.SetParameterLowerBound(&a1, 0, 0.0);
  problem.SetParameterLowerBound(&b, 0, 1e-12 * b);
  ceres::Solver::Options options;
  options.linear_solver_type = ceres::DENSE_QR;
  options.max_num_iterations = 200;
  options.function_tolerance = 1e-14;
  options.parameter_tolerance = 1e-14;
  options.logging_type = ceres::SILENT;
  ceres::Solver::Summary summary;
  ceres::Solve(options, &problem, &summary);
  if (!summary.IsSolutionUsable()) throw SolverError("pressure calibration did not converge: " + summary.message);

  PressureFit fit;
  fit.calibration.a1 = a1;
  fit.calibration.a2 = b - a1 * x_min;
  fit.calibration.a3 = a3;
  double squares = 0;
  for (const auto& s : samples) {
    const double r = predicted_pressure(fit.calibration, s) - s.true_pressure_N_per_mm2;
    fit.residuals_N_per_mm2.push_back(r);
    squares += r * r;
    fit.max_abs_N_per_mm2 = std::max(fit.max_abs_N_per_mm2, std::abs(r));
  }
  fit.rms_N_per_mm2 = std::sqrt(squares / n);
  return fit;
}

}  // namespace emit
