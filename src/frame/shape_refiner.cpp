#include "emit/frame/shape_refiner.hpp"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdlib>
#include <numbers>
#include <tuple>

#include <ceres/ceres.h>

#include "emit/core/errors.hpp"
#include "emit/core/option_check.hpp"
#include "emit/sensor/surface.hpp"

namespace emit {

void ShapeOptions::validate() const {
  option_check::positive("ShapeOptions", "log_radius_std", log_radius_std);
  option_check::positive("ShapeOptions", "elongation_std", elongation_std);
  option_check::non_negative("ShapeOptions", "model_error_fraction", model_error_fraction);
  option_check::at_least("ShapeOptions", "max_iterations", max_iterations, 1);
}

namespace {

constexpr int ellipse_parameters = 6;
constexpr int trial_iterations =
    8;  // a merge tried: enough to tell, its winner then solved in full  // x, y [mm], ℓ, p, q, log g [log S/mm²]
using Parameters = std::array<double, ellipse_parameters>;

Parameters to_parameters(const Ellipse& e) {
  return {e.x_mm, e.y_mm, e.log_radius, e.p, e.q, std::log(e.conductance_S_per_mm2)};
}
Ellipse to_ellipse(const double* p) { return {p[0], p[1], p[2], p[3], p[4], std::exp(p[5])}; }

/// The bound on p and q: the major semi-axis a = e^(ℓ+e) within about half the sheet (|p|, |q| ≤
/// this keeps e = √(p² + q²) under √2 times it).
double elongation_bound(const Eigen::AlignedBox2d& box, double log_radius) {
  return std::max(0.0, std::log(0.5 * box.sizes().minCoeff()) - log_radius) / std::sqrt(2.0);
}

/// The shape prior's residuals: (ℓ − ℓ₀)/σ_ℓ, p/σ_e, q/σ_e (shape_refiner.hpp).
class ShapePrior : public ceres::SizedCostFunction<3, ellipse_parameters> {
 public:
  ShapePrior(double log_radius, const ShapeOptions& o)
      : log_radius_(log_radius), radius_std_(o.log_radius_std), elongation_std_(o.elongation_std) {}
  bool Evaluate(double const* const* parameters, double* residuals, double** jacobians) const override {
    const double* p = parameters[0];
    residuals[0] = (p[2] - log_radius_) / radius_std_;
    residuals[1] = p[3] / elongation_std_;
    residuals[2] = p[4] / elongation_std_;
    if (jacobians && jacobians[0]) {
      std::fill(jacobians[0], jacobians[0] + std::ptrdiff_t{3} * ellipse_parameters, 0.0);
      jacobians[0][0 * ellipse_parameters + 2] = 1 / radius_std_;
      jacobians[0][1 * ellipse_parameters + 3] = 1 / elongation_std_;
      jacobians[0][2 * ellipse_parameters + 4] = 1 / elongation_std_;
    }
    return true;
  }

 private:
  double log_radius_, radius_std_, elongation_std_;
};

}  // namespace

/// Ceres's view of the refit: residuals (predicted − measured)/σ for all ellipses at once, with
/// the analytic Jacobian (ellipse_contact.hpp's ∂C, ∂C/∂log g = C, frame_predictor.hpp's derivative).
class EllipseMisfit : public ceres::CostFunction {
 public:
  EllipseMisfit(ShapeRefiner& refiner, const Vector& dV, int count) : r_(refiner), dV_(dV), count_(count) {
    for (int i = 0; i < count; ++i) mutable_parameter_block_sizes()->push_back(ellipse_parameters);
    set_num_residuals(refiner.shared_.measurements().size());
  }

  bool Evaluate(double const* const* parameters, double* residuals, double** jacobians) const override {
    const FitPrecompute& shared = r_.shared_;
    r_.load_.clear();
    ranges_.clear();
    for (int i = 0; i < count_; ++i) {
      const std::size_t begin = r_.load_.triangles.size();
      r_.integrator_.integrate(to_ellipse(parameters[i]), r_.load_, jacobians != nullptr);
      ranges_.emplace_back(begin, r_.load_.triangles.size());
    }
    r_.predictor_.predict(r_.load_.triangles, r_.load_.local_S, shared.sensor().drive_voltage_V, r_.frame_);
    const MeasurementSet& m = shared.measurements();
    bool finite = true;
    for (int k = 0; k < m.size(); ++k) {
      residuals[k] = (r_.frame_.data()[m.frame_index[k]] - dV_[k]) * r_.weight_[k];
      finite = finite && std::isfinite(residuals[k]);
    }
    if (!finite) return false;  // a step too far: Ceres shrinks it
    if (!jacobians) return true;
    for (int i = 0; i < count_; ++i) {
      if (!jacobians[i]) continue;
      for (int j = 0; j < ellipse_parameters; ++j) {
        direction_.assign(r_.load_.triangles.size(), Eigen::Matrix3d::Zero());
        for (std::size_t t = ranges_[static_cast<std::size_t>(i)].first;
             t < ranges_[static_cast<std::size_t>(i)].second; ++t)
          direction_[t] = j == 5 ? r_.load_.local_S[t] : r_.load_.d_local_S[t][static_cast<std::size_t>(j)];
        r_.predictor_.derivative(r_.load_.triangles, direction_, d_frame_);
        for (int k = 0; k < m.size(); ++k)
          jacobians[i][k * ellipse_parameters + j] = d_frame_.data()[m.frame_index[k]] * r_.weight_[k];
      }
    }
    return true;
  }

 private:
  ShapeRefiner& r_;
  const Vector& dV_;
  int count_;
  mutable std::vector<std::pair<std::size_t, std::size_t>> ranges_;
  mutable std::vector<Eigen::Matrix3d> direction_;
  mutable Frame d_frame_;
};

ShapeRefiner::ShapeRefiner(const FitPrecompute& shared, ShapeOptions options)
    : shared_(shared), options_(options), integrator_(shared.integrator()), predictor_(shared.mesh(), shared.green()) {
  options.validate();
  predictor_.set_series_resistance(shared.sensor().series_resistance_ohm);
}

Frame ShapeRefiner::predict(const std::vector<Ellipse>& ellipses) {
  load_.clear();
  for (const Ellipse& e : ellipses) integrator_.integrate(e, load_);
  predictor_.predict(load_.triangles, load_.local_S, shared_.sensor().drive_voltage_V, frame_);
  return frame_;
}

/// Levenberg–Marquardt on all ellipses at once, from `parameters` (updated). The area is held
/// (ShapeOptions): the prior's residual on ℓ is 0 and stays so. \return χ² (the frame's and the
/// prior's residuals, in σ).
double ShapeRefiner::solve(const Vector& dV, std::vector<std::array<double, 6>>& parameters, int iterations,
                           const std::vector<bool>& round) {
  const int count = static_cast<int>(parameters.size());
  ceres::Problem problem;
  std::vector<double*> blocks;
  blocks.reserve(parameters.size());
  for (Parameters& p : parameters) blocks.push_back(p.data());
  problem.AddResidualBlock(new EllipseMisfit(*this, dV, count), nullptr, blocks);
  const Eigen::AlignedBox2d& box = shared_.centre_box();
  const double log_g = std::log(shared_.sensor().contact.conductance_S_per_mm2(0.1));
  for (std::size_t i = 0; i < blocks.size(); ++i) {
    double* p = blocks[i];
    // e bounded so that a = e^(ℓ+e) stays under half the sheet: a long ellipse's patch is the
    // prediction's cost (its cube), and LM's trial steps would otherwise sweep the whole sheet.
    const double max_elongation = elongation_bound(box, p[2]);
    problem.AddResidualBlock(new ShapePrior(p[2], options_), nullptr, p);
    problem.SetParameterLowerBound(p, 0, box.min().x());
    problem.SetParameterUpperBound(p, 0, box.max().x());
    if (!is_sleeve(shared_.sensor().shape)) {  // around a sleeve the chart is periodic: no bound
      problem.SetParameterLowerBound(p, 1, box.min().y());
      problem.SetParameterUpperBound(p, 1, box.max().y());
    }
    for (int j : {3, 4}) {  // the major semi-axis within about half the sheet
      problem.SetParameterLowerBound(p, j, -max_elongation);
      problem.SetParameterUpperBound(p, j, max_elongation);
    }
    problem.SetParameterLowerBound(p, 5, log_g - 16);
    problem.SetParameterUpperBound(p, 5, log_g + 16);
    if (i < round.size() && round[i])  // held round: its elongation is not worth its parameters
      problem.SetManifold(p, new ceres::SubsetManifold(ellipse_parameters, {2, 3, 4}));
    else problem.SetManifold(p, new ceres::SubsetManifold(ellipse_parameters, {2}));  // the area is held
  }
  ceres::Solver::Options solver;
  solver.linear_solver_type = ceres::DENSE_QR;
  solver.max_num_iterations = iterations;
  solver.logging_type = ceres::SILENT;
  solver.function_tolerance = 1e-8;
  solver.parameter_tolerance = 1e-8;
  ceres::Solver::Summary summary;
  ceres::Solve(solver, &problem, &summary);
  for (Parameters& p : parameters) p[1] = wrapped_chart_mm(shared_.sensor().shape, {p[0], p[1]}).y();
  return 2 * summary.final_cost;
}

namespace {

/// One ellipse for two, started where the frame puts it: at their conductance-weighted centre
/// (b's chart point seen from a's, the short way round a sleeve), with their total conductance,
/// and the traceless part of their combined second moment (each ellipse's own, exp(2L)/4, plus the
/// spread of their centres: the parallel-axis theorem; weights G = g A). That quadrupole is the
/// first shape term a frame carries (docs/physics.md, "Contact shapes"), so the merged ellipse of
/// the held area ℓ₀ starts at the angle φ of the moment's major axis and the elongation whose
/// quadrupole is the pair's: e^(2ℓ₀) sinh(2e)/4 = (λ₁ − λ₂)/2. Started round (as before), a bar's
/// two halves took more than a trial's iterations to become one long ellipse, and the merge was
/// refused: a bar at (20, 40) mm, 30°, stayed two. `max_elongation` is the bound solve() puts on p
/// and q. On a curved sheet the chart's offsets stand for the tangent plane's (a start only).
Parameters merged(const Parameters& a, const Parameters& b, double max_elongation,
                  const EllipseContactIntegrator& charts) {
  const double ga = std::exp(a[5] + 2 * a[2]), gb = std::exp(b[5] + 2 * b[2]);  // G/π of each
  const double w = ga / (ga + gb);
  const Vector2 to_b = charts.chart_offset({b[0], b[1]}, {a[0], a[1]});
  Eigen::Matrix2d moment = Eigen::Matrix2d::Zero();
  for (const auto& [c, weight, offset] :
       {std::tuple{&a, w, Vector2(-(1 - w) * to_b)}, std::tuple{&b, 1 - w, Vector2(w * to_b)}}) {
    const Parameters& e = *c;
    const double elongation = std::hypot(e[3], e[4]);
    // exp(2L) = e^(2ℓ) (cosh 2e I + sinh(2e)/e [[p, q], [q, −p]])
    const double s = elongation > 0 ? std::sinh(2 * elongation) / elongation : 2;
    Eigen::Matrix2d own;
    own << std::cosh(2 * elongation) + s * e[3], s * e[4], s * e[4], std::cosh(2 * elongation) - s * e[3];
    moment += weight * (std::exp(2 * e[2]) / 4 * own + offset * offset.transpose());
  }
  const double half_difference = std::hypot((moment(0, 0) - moment(1, 1)) / 2, moment(0, 1));  // (λ₁ − λ₂)/2
  const double two_phi = std::atan2(2 * moment(0, 1), moment(0, 0) - moment(1, 1));
  const double elongation = std::min(std::asinh(4 * half_difference * std::exp(-2 * a[2])) / 2, max_elongation);
  return {a[0] + (1 - w) * to_b.x(),      a[1] + (1 - w) * to_b.y(),      a[2],
          elongation * std::cos(two_phi), elongation * std::sin(two_phi), std::log(ga + gb) - 2 * a[2]};
}

/// Whether two contacts may be one region: the gap between their ellipses' circumscribed circles
/// under the separation that tells two presses apart (three of the fit's held radii, as
/// FitPrecompute::plausible_separation_mm).
/// Farther apart, one ellipse cannot cover both without leaving a frame the merge never pays for
/// (four fingers 20 mm apart: 7.3 s of merge trials a frame, BM_ShapesFrameFour, none merged).
/// On a curved sheet the centres' distance is the chart's (the short way round a sleeve): a cap's is
/// shorter than the surface's, so the test lets more pairs through, never fewer.
/// `reach_a` and `reach_b`: the ellipses' semi-major axes as fitted free (a contact held round
/// reaches as far as its free fit did: a bar's halves, held round, are still a bar's).
bool within_reach(const Parameters& a, const Parameters& b, double reach_a, double reach_b, double separation_mm,
                  const EllipseContactIntegrator& charts) {
  return charts.chart_offset({b[0], b[1]}, {a[0], a[1]}).norm() - reach_a - reach_b < separation_mm;
}

}  // namespace

const std::vector<RefinedContact>& ShapeRefiner::refine(const Vector& dV, const std::vector<Disc>& discs,
                                                        const AreaPrior& prior) {
  if (dV.size() != shared_.measurements().size())
    throw InvalidInput("contact shapes: one value per measurement is needed");
  if (!(prior.radius_mm > 0)) throw InvalidInput("contact shapes: the prior's radius must be positive");
  if (!(prior.log_radius_std > 0)) throw InvalidInput("contact shapes: the prior's σ must be positive");
  const double typical_radius_mm = prior.radius_mm;
  result_.clear();
  if (discs.empty()) return result_;
  const double log_radius = std::log(typical_radius_mm);
  weight_.resize(dV.size());
  for (Index k = 0; k < dV.size(); ++k)
    weight_[k] = 1 / std::hypot(shared_.noise_V(), options_.model_error_fraction * dV[k]);
  // Start: each disc's total conductance spread over the prior's disc.
  std::vector<Parameters> parameters;
  parameters.reserve(discs.size());
  for (const Disc& d : discs) {
    Ellipse e = Ellipse::round(d);
    e.log_radius = log_radius;
    e.conductance_S_per_mm2 *= d.radius_mm * d.radius_mm / (typical_radius_mm * typical_radius_mm);
    parameters.push_back(to_parameters(e));
  }
  double chi2 = solve(dV, parameters, options_.max_iterations);
  // Several contacts: held round together unless their elongations lower χ² by more than their
  // parameters are worth (BIC: 2 ln M a contact, as the merges below). Free, the elongations of
  // several round presses took up the model's error: four fingers 20 mm apart came back as sticks
  // 12–16 mm long in a pinwheel (BM_ShapesFrameFourTracked), near enough for merge trials. Not a
  // cure: two fingers 15 mm apart still gain Δχ² 47 as two sticks pushed apart (docs/physics.md,
  // "Contact shapes").
  const double log_M = std::log(static_cast<double>(shared_.measurements().size()));
  std::vector<bool> round(parameters.size(), false);
  std::vector<double> reach(parameters.size());  // a contact held round reaches as far as its free fit
  for (std::size_t i = 0; i < reach.size(); ++i) reach[i] = to_ellipse(parameters[i].data()).semi_major_mm();
  if (parameters.size() > 1) {
    std::vector<Parameters> trial = parameters;
    for (Parameters& p : trial) p[3] = p[4] = 0;
    const std::vector<bool> all_round(parameters.size(), true);
    const double c = solve(dV, trial, options_.max_iterations, all_round);
    if (c < chi2 + 2 * log_M * static_cast<double>(trial.size()))
      parameters = std::move(trial), round = all_round, chi2 = c;
  }
  // Which regions the frame supports: two contacts merged into one where that costs less χ² than
  // a contact's parameters are worth (BIC: 6 ln M). The disc fit covers a bar with two discs.
  const double worth = ellipse_parameters * log_M;
  while (parameters.size() > 1) {
    std::vector<Parameters> best;
    std::vector<bool> best_round;
    std::vector<double> best_reach;
    double best_chi2 = 0;
    for (std::size_t i = 0; i < parameters.size(); ++i)
      for (std::size_t j = i + 1; j < parameters.size(); ++j) {
        if (!within_reach(parameters[i], parameters[j], reach[i], reach[j], 3 * shared_.options().prior_radius_mm,
                          integrator_))
          continue;
        std::vector<Parameters> trial;
        std::vector<bool> trial_round;
        std::vector<double> trial_reach;
        for (std::size_t k = 0; k < parameters.size(); ++k)
          if (k != i && k != j)
            trial.push_back(parameters[k]), trial_round.push_back(round[k]), trial_reach.push_back(reach[k]);
        trial.push_back(merged(parameters[i], parameters[j], elongation_bound(shared_.centre_box(), parameters[i][2]),
                               integrator_));
        trial_round.push_back(false);
        const double c = solve(dV, trial, trial_iterations, trial_round);
        trial_reach.push_back(to_ellipse(trial.back().data()).semi_major_mm());
        if (c < chi2 + worth && (best.empty() || c < best_chi2))
          best = std::move(trial), best_round = std::move(trial_round), best_reach = std::move(trial_reach),
          best_chi2 = c;
      }
    if (best.empty()) break;
    parameters = std::move(best), round = std::move(best_round), reach = std::move(best_reach);
    chi2 = solve(dV, parameters, options_.max_iterations, round);
  }
  covariances(dV, parameters, chi2, prior.log_radius_std);
  return result_;
}

/// Each contact's 1σ from the covariance at the solution, (JᵀJ)⁻¹ over the frame's rows and the
/// prior's, the held area's σ the prior's.
void ShapeRefiner::covariances(const Vector& dV, const std::vector<std::array<double, 6>>& parameters, double chi2,
                               double log_radius_std) {
  const int count = static_cast<int>(parameters.size());
  const int M = shared_.measurements().size(), n = ellipse_parameters * count;
  Matrix J = Matrix::Zero(M + 3 * count, n);
  {
    std::vector<Eigen::Matrix<double, Eigen::Dynamic, ellipse_parameters, Eigen::RowMajor>>
        jac(static_cast<std::size_t>(count),
            Eigen::Matrix<double, Eigen::Dynamic, ellipse_parameters, Eigen::RowMajor>(M, ellipse_parameters));
    std::vector<double*> jacobians;
    std::vector<const double*> values;
    for (int i = 0; i < count; ++i)
      jacobians.push_back(jac[static_cast<std::size_t>(i)].data()),
          values.push_back(parameters[static_cast<std::size_t>(i)].data());
    Vector residuals(M);
    const EllipseMisfit cost(*this, dV, count);
    if (cost.Evaluate(values.data(), residuals.data(), jacobians.data())) {
      for (int i = 0; i < count; ++i)
        J.block(0, Index{ellipse_parameters} * i, M, ellipse_parameters) = jac[static_cast<std::size_t>(i)];
      rms_misfit_V_ = std::sqrt(residuals.cwiseQuotient(weight_).squaredNorm() / M);
    }
    for (int i = 0; i < count; ++i) {
      J(M + 3 * i + 1, ellipse_parameters * i + 3) = 1 / options_.elongation_std;
      J(M + 3 * i + 2, ellipse_parameters * i + 4) = 1 / options_.elongation_std;
    }
  }
  for (int i = 0; i < count; ++i) J.col(ellipse_parameters * i + 2).setZero();  // ℓ held: not the frame's
  // Scaled up by the misfit per degree of freedom where the model misfits more than the noise.
  const double scale = std::max(1.0, chi2 / std::max(1.0, static_cast<double>(M - n)));
  Matrix covariance = scale * (J.transpose() * J).completeOrthogonalDecomposition().pseudoInverse();
  for (int i = 0; i < count; ++i) {  // the held ℓ: the prior's σ, uncorrelated
    const int l = ellipse_parameters * i + 2;
    covariance.row(l).setZero();
    covariance.col(l).setZero();
    covariance(l, l) = log_radius_std * log_radius_std;
  }
  for (int i = 0; i < count; ++i) {
    const Ellipse e = to_ellipse(parameters[static_cast<std::size_t>(i)].data());
    const Eigen::Matrix<double, ellipse_parameters, ellipse_parameters> C =
        covariance.block<ellipse_parameters, ellipse_parameters>(Index{ellipse_parameters} * i,
                                                                 Index{ellipse_parameters} * i);
    const auto std_of = [&](const Eigen::Matrix<double, ellipse_parameters, 1>& gradient) {
      return std::sqrt(std::max(0.0, gradient.dot(C * gradient)));
    };
    using Gradient = Eigen::Matrix<double, ellipse_parameters, 1>;
    const Gradient log_area = (Gradient() << 0, 0, 2, 0, 0, 0).finished();  // log A = log π + 2ℓ
    // The frame pins G = g A whatever the held A: its σ is log g's with ℓ held, independent of A's.
    const Gradient log_total = (Gradient() << 0, 0, 0, 0, 0, 1).finished();
    const double elongation = e.elongation(), e2 = std::max(elongation * elongation, 1e-12);
    const Gradient angle = (Gradient() << 0, 0, 0, -e.q / (2 * e2), e.p / (2 * e2), 0).finished();
    const Gradient stretch =
        (Gradient() << 0, 0, 0, elongation > 0 ? e.p / elongation : 1, elongation > 0 ? e.q / elongation : 0, 0)
            .finished();
    RefinedContact r;
    r.ellipse = e;
    r.x_std_mm = std::sqrt(std::max(0.0, C(0, 0)));
    r.y_std_mm = std::sqrt(std::max(0.0, C(1, 1)));
    r.log_area_std = std_of(log_area);
    r.log_conductance_std = std_of(log_total);
    r.orientation_std_rad = std::min(std_of(angle), std::numbers::pi / 2);
    r.elongation_std = std_of(stretch);
    r.log_conductance_log_area_cov = 0;
    result_.push_back(r);
  }
}

}  // namespace emit
