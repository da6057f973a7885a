#include "emit/reconstruct/calibration.hpp"

#include <algorithm>
#include <cmath>

#include <ceres/ceres.h>

#include "emit/errors.hpp"

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

double predicted_pressure(const PressureCalibration& calibration, const PressureSample& sample) {
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
  if (samples.size() < 3) throw InvalidInput("calibration needs at least 3 presses, got " + std::to_string(samples.size()));
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
  const double n = static_cast<double>(samples.size());
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
  fit.calibration.calibrated = true;
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

namespace {

struct RelativeResistanceResidual {
  double pressure, resistance;
  template <class T>
  bool operator()(const T* log_alpha, const T* gamma, T* residual) const {
    residual[0] = ceres::exp(log_alpha[0] + gamma[0] * std::log(pressure)) / resistance - 1.0;
    return true;
  }
};

}  // namespace

ContactLawFit fit_contact_law(const std::vector<double>& pressure, const std::vector<double>& resistance) {
  if (pressure.size() != resistance.size() || pressure.size() < 2)
    throw InvalidInput("the contact law needs at least 2 (pressure, resistance) pairs");
  for (std::size_t i = 0; i < pressure.size(); ++i)
    if (!(pressure[i] > 0) || !(resistance[i] > 0))
      throw InvalidInput("pair " + std::to_string(i) + ": pressure and resistance must be positive");
  // Log-linear start, then the relative-error fit.
  double sx = 0, sy = 0, sxx = 0, sxy = 0;
  const double n = static_cast<double>(pressure.size());
  for (std::size_t i = 0; i < pressure.size(); ++i) {
    const double x = std::log(pressure[i]), y = std::log(resistance[i]);
    sx += x, sy += y, sxx += x * x, sxy += x * y;
  }
  double gamma = (n * sxy - sx * sy) / (n * sxx - sx * sx);
  double log_alpha = (sy - gamma * sx) / n;
  ceres::Problem problem;
  for (std::size_t i = 0; i < pressure.size(); ++i)
    problem.AddResidualBlock(new ceres::AutoDiffCostFunction<RelativeResistanceResidual, 1, 1, 1>(
                                 new RelativeResistanceResidual{pressure[i], resistance[i]}),
                             nullptr, &log_alpha, &gamma);
  ceres::Solver::Options options;
  options.logging_type = ceres::SILENT;
  ceres::Solver::Summary summary;
  ceres::Solve(options, &problem, &summary);
  ContactLawFit fit;
  fit.alpha = std::exp(log_alpha);
  fit.gamma = gamma;
  double squares = 0;
  for (std::size_t i = 0; i < pressure.size(); ++i) {
    const double r = fit.alpha * std::pow(pressure[i], gamma) / resistance[i] - 1.0;
    squares += r * r;
  }
  fit.rms_relative = std::sqrt(squares / n);
  return fit;
}

FittedLawCalibration calibrate_fitted_contact_law(Reconstructor& reconstructor, const std::vector<Frame>& frames,
                                                  const std::vector<double>& true_pressure_N_per_mm2,
                                                  const ContactLaw& nominal) {
  if (!reconstructor.fit_result()) throw InvalidInput("calibrating contact fitting needs a reconstructor that fits");
  if (frames.size() != true_pressure_N_per_mm2.size()) throw InvalidInput("one true pressure per frame is needed");
  std::vector<double> pressure, resistance;  // true P, and 1/g of the fitted disc [Ω·mm²]
  for (std::size_t f = 0; f < frames.size(); ++f) {
    reconstructor.process(frames[f]);
    const FitResult& fit = *reconstructor.fit_result();
    if (fit.contacts.empty()) continue;
    pressure.push_back(true_pressure_N_per_mm2[f]);
    resistance.push_back(1 / fit.contacts[0].disc.conductance_S_per_mm2);
  }
  const ContactLawFit fit = fit_contact_law(pressure, resistance);
  FittedLawCalibration result{{fit.alpha, fit.gamma, nominal.min_pressure_N_per_mm2}, 0, 0, pressure.size()};
  double sum_sq = 0;
  for (std::size_t i = 0; i < pressure.size(); ++i) {
    const double error = result.law.pressure_N_per_mm2(1 / resistance[i]) - pressure[i];
    sum_sq += error * error;
    result.max_abs_N_per_mm2 = std::max(result.max_abs_N_per_mm2, std::abs(error));
  }
  result.rms_N_per_mm2 = std::sqrt(sum_sq / static_cast<double>(pressure.size()));
  return result;
}

}  // namespace emit
