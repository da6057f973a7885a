#include "emit/calibrate/contact_law_calibration.hpp"

#include <algorithm>
#include <cmath>

#include <ceres/ceres.h>

#include "emit/core/errors.hpp"
#include "emit/frame/reconstructor.hpp"

namespace emit {

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
  const auto n = static_cast<double>(pressure.size());
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

namespace {

/// A calibration with the nominal law and nothing else: the fitted discs' conductance as it comes.
FitCalibration nominal_law(const ContactLaw& law) {
  FitCalibration c;
  c.contact_law = law;
  return c;
}

}  // namespace

FittedLawCalibration calibrate_fitted_contact_law(const ReconstructionModel& model, const FitPrecompute& fitting,
                                                  const Reference& reference, const std::vector<Frame>& frames,
                                                  const std::vector<double>& true_pressure_N_per_mm2,
                                                  const ContactLaw& nominal, const FrameOptions& options) {
  if (frames.size() != true_pressure_N_per_mm2.size()) throw InvalidInput("one true pressure per frame is needed");
  Reconstructor reconstructor(model, fitting, nominal_law(nominal), options);
  reconstructor.set_reference(reference);
  std::vector<double> pressure, resistance;  // true P, and 1/g of the fitted disc [Ω·mm²]
  for (std::size_t f = 0; f < frames.size(); ++f) {
    reconstructor.process(frames[f]);
    const FitResult& fitted = *reconstructor.fit_result();
    if (fitted.contacts.empty()) continue;
    pressure.push_back(true_pressure_N_per_mm2[f]);
    resistance.push_back(1 / fitted.contacts[0].disc.conductance_S_per_mm2);
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
