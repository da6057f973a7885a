#include "emit/calibrate/sheet_calibration.hpp"

#include <cmath>
#include <cstdio>

#include <ceres/ceres.h>

#include "emit/core/errors.hpp"
#include "emit/model/green_function.hpp"
#include "emit/sensor/adc.hpp"

namespace emit {

namespace {

/// The presses' misfits (predicted − measured)/σ for a sheet correction θ: the Green's function
/// of the corrected sheet (on the columns the presses and electrodes need only), then per press
/// a 1-D Gauss–Newton on its log conductance, warm-started from the last evaluation.
class PressesMisfit {
 public:
  PressesMisfit(const Sensor& sensor, const Mesh& mesh, const MeasurementSet& measurements,
                const std::vector<Vector>& dV, const std::vector<Vector2>& centres_mm, const FitOptions& options)
      : sensor_(sensor),
        mesh_(mesh),
        measurements_(measurements),
        dV_(dV),
        noise_V_(reading_noise_V(sensor.adc)),
        box_(SheetCorrection::identity_over(mesh)) {
    const DiscContactIntegrator integrator(mesh, options.edge_mm);
    const ElectrodeDofs dofs = number_electrode_dofs(mesh);
    for (int e = 0; e < dofs.electrode_count; ++e) columns_.push_back(e);  // electrode e is dof e
    for (const Vector2& c : centres_mm) {
      if (!mesh.contains_xy(c))
        throw InvalidInput("sheet calibration: a press centre (" + std::to_string(c.x()) + ", " +
                           std::to_string(c.y()) + ") mm is off the sheet");
      DiscLoad load;
      integrator.integrate({c.x(), c.y(), options.prior_radius_mm, 1.0}, load);  // g = 1: C is linear in g
      for (Index t : load.triangles)
        for (int k = 0; k < 3; ++k) columns_.push_back(dofs.dof_of_node[mesh.triangles(t, k)]);
      unit_loads_.push_back(std::move(load));
    }
    log_g_.assign(dV.size(), std::log(sensor.contact.conductance_S_per_mm2(0.1)));
  }

  int residual_count() const { return measurements_.size() * static_cast<int>(dV_.size()); }

  SheetCorrection correction(const double* theta) const {
    SheetCorrection c = box_;
    for (int k = 0; k < SheetCorrection::terms; ++k) c.log_conductance[static_cast<std::size_t>(k)] = theta[k];
    return c;
  }

  /// For ceres::DynamicNumericDiffCostFunction.
  bool operator()(double const* const* theta, double* residuals) const {
    const SheetCorrection c = correction(theta[0]);
    const DenseGreenFunction green =
        dense_green_function(mesh_, c.element_conductance_S(mesh_, sensor_.sheet_resistance_ohm_per_sq), columns_);
    FramePredictor predictor(mesh_, green);
    const int M = measurements_.size();
    for (std::size_t i = 0; i < dV_.size(); ++i)
      if (!fit_press(predictor, i, residuals + static_cast<std::ptrdiff_t>(i) * M)) return false;
    return true;
  }

 private:
  /// Gauss–Newton on s = log g (∂C/∂s = C); leaves the press's residuals in `residuals`.
  bool fit_press(FramePredictor& predictor, std::size_t i, double* residuals) const {
    const DiscLoad& unit = unit_loads_[i];
    const int M = measurements_.size();
    double& s = log_g_[i];
    for (int iteration = 0; iteration < 40; ++iteration) {
      scaled_.resize(unit.local_S.size());
      for (std::size_t t = 0; t < scaled_.size(); ++t) scaled_[t] = std::exp(s) * unit.local_S[t];
      predictor.predict(unit.triangles, scaled_, sensor_.drive_voltage_V, frame_);
      predictor.derivative(unit.triangles, scaled_, d_frame_);
      double jr = 0, jj = 0;
      for (int r = 0; r < M; ++r) {
        const int at = measurements_.frame_index[static_cast<std::size_t>(r)];
        residuals[r] = (frame_.data()[at] - dV_[i][r]) / noise_V_;
        const double j = d_frame_.data()[at] / noise_V_;
        jr += j * residuals[r], jj += j * j;
      }
      if (!std::isfinite(jr) || !(jj > 0)) return false;
      const double step = std::clamp(-jr / jj, -2.0, 2.0);
      if (std::abs(step) < 1e-12) break;
      s += step;
    }
    return true;
  }

  const Sensor& sensor_;
  const Mesh& mesh_;
  const MeasurementSet& measurements_;
  const std::vector<Vector>& dV_;
  double noise_V_;
  SheetCorrection box_;
  std::vector<int> columns_;
  std::vector<DiscLoad> unit_loads_;
  mutable std::vector<double> log_g_;
  mutable std::vector<Eigen::Matrix3d> scaled_;
  mutable Frame frame_, d_frame_;
};

/// θ_k / σ_θ: a weak prior, so that a term the presses cannot see stays at 0.
struct CorrectionPrior {
  static constexpr double log_std = 1.0;  // a factor e over half the sheet is one σ
  template <typename T>
  bool operator()(const T* theta, T* residual) const {
    for (int k = 0; k < SheetCorrection::terms; ++k) residual[k] = theta[k] / log_std;
    return true;
  }
};

double rms_V(const std::vector<double>& residuals, double noise_V) {
  double sum = 0;
  for (double r : residuals) sum += r * r;
  return noise_V * std::sqrt(sum / static_cast<double>(residuals.size()));
}

class Progress : public ceres::IterationCallback {
 public:
  Progress(const std::function<void(const std::string&)>& say, int residuals, double noise_V)
      : say_(say), residuals_(residuals), noise_V_(noise_V) {}
  ceres::CallbackReturnType operator()(const ceres::IterationSummary& s) override {
    char line[128];
    std::snprintf(line, sizeof line, "sheet calibration: iteration %d, misfit %.3f mV rms", s.iteration,
                  1e3 * noise_V_ * std::sqrt(2 * s.cost / residuals_));
    say_(line);
    return ceres::SOLVER_CONTINUE;
  }

 private:
  const std::function<void(const std::string&)>& say_;
  int residuals_;
  double noise_V_;
};

}  // namespace

SheetCalibration calibrate_sheet(const Sensor& sensor, const Mesh& fit_mesh, const MeasurementSet& measurements,
                                 const std::vector<Vector>& dV, const std::vector<Vector2>& centres_mm,
                                 const FitOptions& options, const std::function<void(const std::string&)>& progress) {
  if (dV.size() != centres_mm.size()) throw InvalidInput("sheet calibration: one centre per press is needed");
  if (dV.size() < 8)
    throw InvalidInput("sheet calibration: " + std::to_string(dV.size()) + " presses; at least 8 are needed");
  for (const Vector& d : dV)
    if (d.size() != measurements.size() || !d.allFinite())
      throw InvalidInput("sheet calibration: a press has a wrong count of readings or a non-finite one");
  const FitOptions resolved = resolved_fit_options(options, sensor, fit_mesh);
  const double noise_V = reading_noise_V(sensor.adc);
  auto* misfit = new PressesMisfit(sensor, fit_mesh, measurements, dV, centres_mm, resolved);
  std::array<double, SheetCorrection::terms> theta{};
  SheetCalibration result;
  result.presses = static_cast<int>(dV.size());
  std::vector<double> residuals(static_cast<std::size_t>(misfit->residual_count()));
  const double* values[] = {theta.data()};
  if (!(*misfit)(values, residuals.data())) throw SolverError("sheet calibration: the nominal sheet's fit failed");
  result.rms_misfit_nominal_V = rms_V(residuals, noise_V);

  ceres::NumericDiffOptions difference;
  difference.relative_step_size = 1e-4;  // θ starts at 0: Ceres then steps by this much absolutely
  auto* cost = new ceres::DynamicNumericDiffCostFunction<PressesMisfit, ceres::FORWARD>(misfit, ceres::TAKE_OWNERSHIP,
                                                                                        difference);
  cost->AddParameterBlock(SheetCorrection::terms);
  cost->SetNumResiduals(misfit->residual_count());
  ceres::Problem problem;
  problem.AddResidualBlock(cost, nullptr, theta.data());
  problem.AddResidualBlock(new ceres::AutoDiffCostFunction<CorrectionPrior, SheetCorrection::terms,
                                                           SheetCorrection::terms>(new CorrectionPrior),
                           nullptr, theta.data());
  for (int k = 0; k < SheetCorrection::terms; ++k) {  // a factor of e² either way at most
    problem.SetParameterLowerBound(theta.data(), k, -2);
    problem.SetParameterUpperBound(theta.data(), k, 2);
  }
  ceres::Solver::Options solver;
  solver.linear_solver_type = ceres::DENSE_QR;
  solver.max_num_iterations = 20;
  // A thousandth of the misfit, or θ to 1e-5: far finer than the presses' noise resolves θ.
  solver.function_tolerance = 1e-3;
  solver.parameter_tolerance = 1e-5;
  solver.logging_type = ceres::SILENT;
  Progress news(progress, misfit->residual_count(), noise_V);
  if (progress) solver.callbacks.push_back(&news);
  ceres::Solver::Summary summary;
  ceres::Solve(solver, &problem, &summary);
  if (!summary.IsSolutionUsable()) throw SolverError("sheet calibration: " + summary.message);

  result.correction = misfit->correction(theta.data());
  if (!(*misfit)(values, residuals.data())) throw SolverError("sheet calibration: the corrected sheet's fit failed");
  result.rms_misfit_corrected_V = rms_V(residuals, noise_V);
  return result;
}

SheetCalibration calibrate_sheet(const Sensor& sensor, const Mesh& fit_mesh, const MeasurementSet& measurements,
                                 const std::vector<Frame>& frames, const Frame& reference, const PressSequence& presses,
                                 const std::function<void(const std::string&)>& progress) {
  if (frames.size() != presses.size()) throw InvalidInput("sheet calibration: one set of presses per frame is needed");
  std::vector<Vector> dV;
  std::vector<Vector2> centres;
  for (std::size_t f = 0; f < frames.size(); ++f) {
    if (presses[f].size() != 1) continue;  // a single press's centre is known; two mix
    dV.push_back(frame_difference(measurements, frames[f], reference));
    centres.emplace_back(presses[f][0].x_mm, presses[f][0].y_mm);
  }
  return calibrate_sheet(sensor, fit_mesh, measurements, dV, centres, {}, progress);
}

}  // namespace emit
