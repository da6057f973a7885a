#include "emit/calibrate/sensor_calibration.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <memory>

#include <ceres/ceres.h>

#include "emit/core/errors.hpp"
#include "emit/mesh/sheet_chart.hpp"
#include "emit/mesh/slide_electrodes.hpp"
#include "emit/model/green_function.hpp"
#include "emit/sensor/adc.hpp"

namespace emit {

namespace {

/// Parameter blocks of the fit, in the units Ceres sees (each about 1 over its plausible range).
struct Blocks {
  std::vector<double> theta;          ///< the sheet correction's log-conductance terms
  std::array<double, 1> log_drive{};  ///< log(E / E_nominal)
  std::vector<double> series;         ///< R_l / series_unit_ohm
  std::vector<double> shift_mm;       ///< each electrode's slide along the border
};
constexpr double series_unit_ohm = 100;
// The priors: the plausible range of a real sheet (twin/realistic_sheet.hpp), one σ each.
constexpr double theta_prior_std = 1.0;  // a factor e over half the sheet
constexpr double log_drive_prior_std = 0.1;
constexpr double series_prior_std = 3.0;  // 300 Ω
constexpr double shift_prior_std_mm = 0.5;
constexpr double shift_bound_mm = 1.5;  // slide_electrodes refuses what its room does not allow

/// The presses' misfits (predicted − measured)/σ for a sensor (θ, E, R): the Green's function of
/// the corrected sheet (on the columns the presses and electrodes need only; kept while θ stays),
/// then per press a 1-D Gauss–Newton on its log conductance, warm-started from the last evaluation.
class PressesMisfit {
 public:
  PressesMisfit(const Sensor& sensor, const Mesh& mesh, const MeasurementSet& measurements,
                const std::vector<Vector>& dV, const std::vector<Vector2>& centres_mm, const FitOptions& options,
                int sheet_terms)
      : sensor_(sensor),
        base_mesh_(mesh),
        measurements_(measurements),
        dV_(dV),
        centres_mm_(centres_mm),
        options_(options),
        noise_V_(reading_noise_V(sensor.adc)),
        box_(SheetCorrection::identity_over(mesh, sheet_terms)) {
    for (const Vector2& c : centres_mm)
      if (!chart_on_sheet(mesh, sensor.shape, c))
        throw InvalidInput("sensor calibration: a press centre (" + std::to_string(c.x()) + ", " +
                           std::to_string(c.y()) + ") mm is off the sheet");
    log_g_.assign(dV.size(), std::log(sensor.contact.conductance_S_per_mm2(0.1)));
  }

  int residual_count() const { return measurements_.size() * static_cast<int>(dV_.size()); }
  int electrode_count() const { return measurements_.electrode_count; }

  SheetCorrection correction(const double* theta) const {
    SheetCorrection c = box_;
    for (int k = 0; k < c.terms(); ++k) c.log_conductance[static_cast<std::size_t>(k)] = theta[k];
    return c;
  }
  double drive_V(const double* log_drive) const { return sensor_.drive_voltage_V * std::exp(log_drive[0]); }
  std::vector<double> series_ohm(const double* series) const {
    std::vector<double> ohm(static_cast<std::size_t>(electrode_count()));
    for (std::size_t e = 0; e < ohm.size(); ++e) ohm[e] = std::max(0.0, series_unit_ohm * series[e]);
    return ohm;
  }

  std::vector<double> shifts(const double* shift) const {
    return std::vector<double>(shift, shift + electrode_count());
  }

  /// For ceres::DynamicNumericDiffCostFunction: blocks θ, log E, R, electrode shifts.
  bool operator()(double const* const* blocks, double* residuals) const {
    const std::vector<double> theta(blocks[0], blocks[0] + box_.terms());
    const std::vector<double> shift = shifts(blocks[3]);
    const bool moved = !predictor_ || shift != cached_shift_;
    if (moved) {  // the electrodes slid: the mesh, the presses' loads and the columns they need
      predictor_.reset();
      try {
        const bool none = std::all_of(shift.begin(), shift.end(), [](double s) { return s == 0; });
        mesh_ = none ? base_mesh_ : slide_electrodes(base_mesh_, sensor_, shift);
      } catch (const InvalidInput&) {
        return false;  // beyond the room to slide: Ceres rejects the step
      }
      integrate_presses();
      cached_shift_ = shift;
    }
    if (moved || theta != cached_theta_) {  // the Green's function only when the sheet changes
      predictor_.reset();
      green_ = dense_green_function(mesh_,
                                    correction(theta.data())
                                        .element_conductance_S(mesh_, sensor_.sheet_resistance_ohm_per_sq),
                                    columns_);
      predictor_ = std::make_unique<FramePredictor>(mesh_, green_);
      cached_theta_ = theta;
    }
    predictor_->set_series_resistance(series_ohm(blocks[2]));
    const double E = drive_V(blocks[1]);
    const int M = measurements_.size();
    for (std::size_t i = 0; i < dV_.size(); ++i)
      if (!fit_press(E, i, residuals + static_cast<std::ptrdiff_t>(i) * M)) return false;
    return true;
  }

 private:
  /// Each press a held disc of unit conductance at its true centre on the current mesh, and the
  /// Green's function's columns they and the electrodes need.
  void integrate_presses() const {
    const DiscContactIntegrator integrator(mesh_, options_.edge_mm, 3, sensor_.shape);
    const ElectrodeDofs dofs = number_electrode_dofs(mesh_);
    columns_.clear();
    for (int e = 0; e < dofs.electrode_count; ++e) columns_.push_back(e);  // electrode e is dof e
    unit_loads_.resize(centres_mm_.size());
    for (std::size_t i = 0; i < centres_mm_.size(); ++i) {
      const Vector2& c = centres_mm_[i];
      unit_loads_[i].clear();  // integrate() appends
      integrator.integrate({c.x(), c.y(), options_.prior_radius_mm, 1.0}, unit_loads_[i]);  // C is linear in g
      for (Index t : unit_loads_[i].triangles)
        for (int k = 0; k < 3; ++k) columns_.push_back(dofs.dof_of_node[mesh_.triangles(t, k)]);
    }
  }

  /// Gauss–Newton on s = log g (∂C/∂s = C); leaves the press's residuals in `residuals`.
  bool fit_press(double E, std::size_t i, double* residuals) const {
    const DiscLoad& unit = unit_loads_[i];
    const int M = measurements_.size();
    double& s = log_g_[i];
    for (int iteration = 0; iteration < 40; ++iteration) {
      scaled_.resize(unit.local_S.size());
      for (std::size_t t = 0; t < scaled_.size(); ++t) scaled_[t] = std::exp(s) * unit.local_S[t];
      predictor_->predict(unit.triangles, scaled_, E, frame_);
      predictor_->derivative(unit.triangles, scaled_, d_frame_);
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
  const Mesh& base_mesh_;
  const MeasurementSet& measurements_;
  const std::vector<Vector>& dV_;
  const std::vector<Vector2>& centres_mm_;
  FitOptions options_;
  double noise_V_;
  SheetCorrection box_;
  mutable Mesh mesh_;  ///< the base mesh with the electrodes slid to cached_shift_
  mutable std::vector<double> cached_shift_;
  mutable std::vector<int> columns_;
  mutable std::vector<DiscLoad> unit_loads_;
  mutable std::vector<double> log_g_;
  mutable std::vector<Eigen::Matrix3d> scaled_;
  mutable Frame frame_, d_frame_;
  mutable std::vector<double> cached_theta_;
  mutable DenseGreenFunction green_;
  mutable std::unique_ptr<FramePredictor> predictor_;
};

/// (x − mean)/σ per parameter: weak priors, so that what the presses cannot see stays nominal.
class Prior : public ceres::CostFunction {
 public:
  Prior(std::vector<double> mean, std::vector<double> std) : mean_(std::move(mean)), std_(std::move(std)) {
    set_num_residuals(static_cast<int>(mean_.size()));
    mutable_parameter_block_sizes()->push_back(static_cast<int>(mean_.size()));
  }
  bool Evaluate(double const* const* x, double* residuals, double** jacobians) const override {
    const std::size_t n = mean_.size();
    for (std::size_t k = 0; k < n; ++k) residuals[k] = (x[0][k] - mean_[k]) / std_[k];
    if (jacobians && jacobians[0]) {
      std::fill(jacobians[0], jacobians[0] + n * n, 0.0);
      for (std::size_t k = 0; k < n; ++k) jacobians[0][k * n + k] = 1.0 / std_[k];
    }
    return true;
  }

 private:
  std::vector<double> mean_, std_;
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
    std::snprintf(line, sizeof line, "sensor calibration: iteration %d, misfit %.3f mV rms", s.iteration,
                  1e3 * noise_V_ * std::sqrt(2 * s.cost / residuals_));
    say_(line);
    return ceres::SOLVER_CONTINUE;
  }

 private:
  const std::function<void(const std::string&)>& say_;
  int residuals_;
  double noise_V_;
};

/// The data's Jacobian at the solution (the priors left out), dense, columns of the free blocks.
Matrix data_jacobian(ceres::Problem& problem, ceres::ResidualBlockId data, const std::vector<double*>& free_blocks) {
  ceres::Problem::EvaluateOptions evaluate;
  evaluate.residual_blocks = {data};
  evaluate.parameter_blocks = free_blocks;
  ceres::CRSMatrix crs;
  double cost = 0;
  problem.Evaluate(evaluate, &cost, nullptr, nullptr, &crs);
  Matrix J = Matrix::Zero(crs.num_rows, crs.num_cols);
  for (int r = 0; r < crs.num_rows; ++r)
    for (int k = crs.rows[static_cast<std::size_t>(r)]; k < crs.rows[static_cast<std::size_t>(r) + 1]; ++k)
      J(r, crs.cols[static_cast<std::size_t>(k)]) = crs.values[static_cast<std::size_t>(k)];
  return J;
}

}  // namespace

void SensorCalibrationOptions::validate() const {
  if (sheet_terms != SheetCorrection::quadratic_terms && sheet_terms != SheetCorrection::cubic_terms)
    throw InvalidInput("sensor calibration: sheet_terms must be 5 (quadratic) or 9 (cubic), got " +
                       std::to_string(sheet_terms));
  if (max_iterations < 1) throw InvalidInput("sensor calibration: max_iterations must be at least 1");
}

SensorCalibration calibrate_sensor(const Sensor& sensor, const Mesh& fit_mesh, const MeasurementSet& measurements,
                                   const std::vector<Vector>& dV, const std::vector<Vector2>& centres_mm,
                                   const SensorCalibrationOptions& options, const FitOptions& fit_options,
                                   const std::function<void(const std::string&)>& progress) {
  options.validate();
  if (dV.size() != centres_mm.size()) throw InvalidInput("sensor calibration: one centre per press is needed");
  if (dV.size() < 8)
    throw InvalidInput("sensor calibration: " + std::to_string(dV.size()) + " presses; at least 8 are needed");
  for (const Vector& d : dV)
    if (d.size() != measurements.size() || !d.allFinite())
      throw InvalidInput("sensor calibration: a press has a wrong count of readings or a non-finite one");
  const int N = measurements.electrode_count;
  if (!sensor.series_resistance_ohm.empty() && static_cast<int>(sensor.series_resistance_ohm.size()) != N)
    throw InvalidInput("sensor calibration: the sensor's series_resistance_ohm has " +
                       std::to_string(sensor.series_resistance_ohm.size()) + " values for " + std::to_string(N) +
                       " electrodes");
  const FitOptions resolved = resolved_fit_options(fit_options, sensor, fit_mesh);
  const double noise_V = reading_noise_V(sensor.adc);
  auto* misfit = new PressesMisfit(sensor, fit_mesh, measurements, dV, centres_mm, resolved, options.sheet_terms);

  Blocks x;
  x.theta.assign(static_cast<std::size_t>(options.sheet_terms), 0.0);
  x.series.assign(static_cast<std::size_t>(N), 0.0);
  x.shift_mm.assign(static_cast<std::size_t>(N), 0.0);
  for (std::size_t e = 0; e < sensor.series_resistance_ohm.size(); ++e)
    x.series[e] = sensor.series_resistance_ohm[e] / series_unit_ohm;
  const std::vector<double> series_prior_mean = x.series;
  SensorCalibration result;
  result.presses = static_cast<int>(dV.size());
  std::vector<double> residuals(static_cast<std::size_t>(misfit->residual_count()));
  const double* values[] = {x.theta.data(), x.log_drive.data(), x.series.data(), x.shift_mm.data()};
  if (!(*misfit)(values, residuals.data())) throw SolverError("sensor calibration: the nominal sensor's fit failed");
  result.rms_misfit_nominal_V = rms_V(residuals, noise_V);

  ceres::NumericDiffOptions difference;
  difference.relative_step_size = 1e-4;  // a parameter at 0: Ceres then steps by this much absolutely
  auto* cost = new ceres::DynamicNumericDiffCostFunction<PressesMisfit, ceres::FORWARD>(misfit, ceres::TAKE_OWNERSHIP,
                                                                                        difference);
  cost->AddParameterBlock(options.sheet_terms);
  cost->AddParameterBlock(1);
  cost->AddParameterBlock(N);
  cost->AddParameterBlock(N);
  cost->SetNumResiduals(misfit->residual_count());
  ceres::Problem problem;
  const ceres::ResidualBlockId data =
      problem.AddResidualBlock(cost, nullptr, x.theta.data(), x.log_drive.data(), x.series.data(), x.shift_mm.data());
  problem.AddResidualBlock(new Prior(std::vector<double>(x.theta.size(), 0.0),
                                     std::vector<double>(x.theta.size(), theta_prior_std)),
                           nullptr, x.theta.data());
  problem.AddResidualBlock(new Prior({0.0}, {log_drive_prior_std}), nullptr, x.log_drive.data());
  problem.AddResidualBlock(new Prior(series_prior_mean, std::vector<double>(x.series.size(), series_prior_std)),
                           nullptr, x.series.data());
  problem.AddResidualBlock(new Prior(x.shift_mm, std::vector<double>(x.shift_mm.size(), shift_prior_std_mm)), nullptr,
                           x.shift_mm.data());
  for (int k = 0; k < options.sheet_terms; ++k) {  // a factor of e² either way at most
    problem.SetParameterLowerBound(x.theta.data(), k, -2);
    problem.SetParameterUpperBound(x.theta.data(), k, 2);
  }
  problem.SetParameterLowerBound(x.log_drive.data(), 0, -0.5);
  problem.SetParameterUpperBound(x.log_drive.data(), 0, 0.5);
  for (int e = 0; e < N; ++e) {  // 0 … 5 kΩ; ±1.5 mm
    problem.SetParameterLowerBound(x.series.data(), e, 0);
    problem.SetParameterUpperBound(x.series.data(), e, 50);
    problem.SetParameterLowerBound(x.shift_mm.data(), e, -shift_bound_mm);
    problem.SetParameterUpperBound(x.shift_mm.data(), e, shift_bound_mm);
  }
  std::vector<double*> free_blocks{x.theta.data()};
  if (options.fit_drive_voltage) free_blocks.push_back(x.log_drive.data());
  else problem.SetParameterBlockConstant(x.log_drive.data());
  if (options.fit_series_resistance) free_blocks.push_back(x.series.data());
  else problem.SetParameterBlockConstant(x.series.data());
  const bool fit_positions = options.fit_electrode_positions && sensor.border.has_value();
  if (fit_positions) free_blocks.push_back(x.shift_mm.data());
  else problem.SetParameterBlockConstant(x.shift_mm.data());

  ceres::Solver::Options solver;
  solver.linear_solver_type = ceres::DENSE_QR;
  solver.max_num_iterations = options.max_iterations;
  // A thousandth of the misfit, or a parameter to 1e-5 of its scale: far finer than the presses'
  // noise resolves them.
  solver.function_tolerance = 1e-3;
  solver.parameter_tolerance = 1e-5;
  solver.logging_type = ceres::SILENT;
  Progress news(progress, misfit->residual_count(), noise_V);
  if (progress) solver.callbacks.push_back(&news);
  ceres::Solver::Summary summary;
  ceres::Solve(solver, &problem, &summary);
  if (!summary.IsSolutionUsable()) throw SolverError("sensor calibration: " + summary.message);

  result.correction = misfit->correction(x.theta.data());
  result.drive_voltage_V = misfit->drive_V(x.log_drive.data());
  result.series_resistance_ohm = misfit->series_ohm(x.series.data());
  result.electrode_shift_mm = x.shift_mm;
  if (!(*misfit)(values, residuals.data())) throw SolverError("sensor calibration: the calibrated sensor's fit failed");
  result.rms_misfit_corrected_V = rms_V(residuals, noise_V);
  const double chi2 = (result.rms_misfit_corrected_V / noise_V) * (result.rms_misfit_corrected_V / noise_V);
  result.chi2_per_reading = chi2;

  // Identifiability: the posterior covariance (JᵀJ + prior)⁻¹ in the blocks' units, inflated by
  // the misfit per reading when the model misfits beyond the noise.
  const Matrix J = data_jacobian(problem, data, free_blocks);
  std::vector<double> prior_std;
  std::vector<std::pair<std::string, double>> named;  // name, unit factor (block unit → reported unit)
  const char* theta_names[] = {"u", "v", "u^2", "uv", "v^2", "u^3", "u^2 v", "u v^2", "v^3"};
  for (int k = 0; k < options.sheet_terms; ++k) {
    named.emplace_back(std::string("sheet log-conductance ") + theta_names[k], 1.0);
    prior_std.push_back(theta_prior_std);
  }
  if (options.fit_drive_voltage) {
    named.emplace_back("drive_voltage_V", result.drive_voltage_V);
    prior_std.push_back(log_drive_prior_std);
  }
  if (options.fit_series_resistance)
    for (int e = 0; e < N; ++e) {
      named.emplace_back("series_resistance_ohm[" + std::to_string(e) + "]", series_unit_ohm);
      prior_std.push_back(series_prior_std);
    }
  if (fit_positions)
    for (int e = 0; e < N; ++e) {
      named.emplace_back("electrode_shift_mm[" + std::to_string(e) + "]", 1.0);
      prior_std.push_back(shift_prior_std_mm);
    }
  Matrix information = J.transpose() * J;
  for (std::size_t k = 0; k < prior_std.size(); ++k)
    information(static_cast<Index>(k), static_cast<Index>(k)) += 1.0 / (prior_std[k] * prior_std[k]);
  const Matrix covariance =
      information.ldlt().solve(Matrix::Identity(information.rows(), information.cols())) * std::max(1.0, chi2);
  std::vector<double> flat = x.theta;
  if (options.fit_drive_voltage) flat.push_back(result.drive_voltage_V);
  if (options.fit_series_resistance)
    for (double r : result.series_resistance_ohm) flat.push_back(r);
  if (fit_positions)
    for (double d : result.electrode_shift_mm) flat.push_back(d);
  for (std::size_t k = 0; k < named.size(); ++k) {
    CalibratedParameter p;
    p.name = named[k].first;
    p.value = flat[k];
    const double std_block = std::sqrt(covariance(static_cast<Index>(k), static_cast<Index>(k)));
    p.std = std_block * named[k].second;
    p.prior_std = prior_std[k] * named[k].second;
    p.determined = std_block < 0.5 * prior_std[k];
    result.parameters.push_back(p);
  }

  // Doubts a user must hear about.
  if (chi2 > 9) {
    char line[256];
    std::snprintf(line, sizeof line,
                  "the calibrated model misfits the presses by %.2f mV rms, %.1f times the readings' noise: a sensor "
                  "file of another sheet, or presses not where the truth file says?",
                  1e3 * result.rms_misfit_corrected_V, std::sqrt(chi2));
    result.warnings.emplace_back(line);
  }
  for (const CalibratedParameter& p : result.parameters) {
    const bool series = p.name.rfind("series", 0) == 0;
    const bool drive = p.name == "drive_voltage_V";
    const bool shift = p.name.rfind("electrode_shift", 0) == 0;
    const bool at_edge = series  ? p.value >= 0.99 * 50 * series_unit_ohm
                         : drive ? std::abs(std::log(p.value / sensor.drive_voltage_V)) > 0.49
                         : shift ? std::abs(p.value) > 0.99 * shift_bound_mm
                                 : false;
    if (at_edge) result.warnings.push_back(p.name + " is at the edge of its plausible range: implausible fit");
  }
  for (int k = 0; k < options.sheet_terms; ++k)
    if (std::abs(x.theta[static_cast<std::size_t>(k)]) > 1.98)
      result.warnings.emplace_back("the sheet's resistance field is at the edge of its plausible range (a factor e^2)");
  return result;
}

SensorCalibration calibrate_sensor(const Sensor& sensor, const Mesh& fit_mesh, const MeasurementSet& measurements,
                                   const std::vector<Frame>& frames, const Frame& reference,
                                   const PressSequence& presses, const SensorCalibrationOptions& options,
                                   const std::function<void(const std::string&)>& progress) {
  if (frames.size() != presses.size()) throw InvalidInput("sensor calibration: one set of presses per frame is needed");
  std::vector<Vector> dV;
  std::vector<Vector2> centres;
  for (std::size_t f = 0; f < frames.size(); ++f) {
    if (presses[f].size() != 1) continue;  // a single press's centre is known; two mix
    dV.push_back(frame_difference(measurements, frames[f], reference));
    centres.push_back(press_chart_mm(sensor.shape, presses[f][0]));
  }
  return calibrate_sensor(sensor, fit_mesh, measurements, dV, centres, options, {}, progress);
}

Sensor calibrated_sensor(const Sensor& nominal, const SensorCalibration& calibration) {
  Sensor sensor = calibration.electrode_shift_mm.empty() || !nominal.border
                      ? nominal
                      : with_electrodes_slid(nominal, calibration.electrode_shift_mm);
  if (calibration.drive_voltage_V > 0) sensor.drive_voltage_V = calibration.drive_voltage_V;
  sensor.series_resistance_ohm = calibration.series_resistance_ohm;
  return sensor;
}

}  // namespace emit
