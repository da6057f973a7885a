#include "emit/calibrate/sensor_calibration.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <limits>
#include <memory>
#include <mutex>
#include <thread>

#include <ceres/ceres.h>

#include "emit/core/errors.hpp"
#include "emit/core/threads.hpp"
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
// The model's own error, in the blocks' units (docs/physics.md, "How sure"): what the fit's model
// (its mesh, a disc of the prior radius for each press, a cubic field) misses of a real sheet, added
// to the statistical σ in quadrature. Measured as the spread of fitted − true (eval/parameter_truth)
// over 24 realistic 60 mm sheets (seeds 1–24, 40 labelled presses each): the floor under which
// 97.5 % of each kind lie within 2σ; checked on other sheets (labelled and unplaced).
constexpr double theta_model_std = 0.023;
constexpr double log_drive_model_std = 0.0035;
constexpr double series_model_std = 1.68;  // × 100 Ω
constexpr double shift_model_std_mm = 0.21;

/// What every evaluation of the presses' misfit shares: the sensor, its base mesh, each press's
/// readings and whether its place is known.
struct Presses {
  const Sensor& sensor;
  const Mesh& base_mesh;
  const MeasurementSet& measurements;
  const std::vector<Vector>& dV;
  std::vector<bool> place_free;  ///< per press: its centre is fitted with it
  FitOptions options;
  double noise_V;
  SheetCorrection box;  ///< the correction's frame (terms, scaling) with θ = 0
  bool any_free = false;

  int readings() const { return measurements.size(); }
  int electrodes() const { return measurements.electrode_count; }
  int residual_count() const { return readings() * static_cast<int>(dV.size()); }
  SheetCorrection correction(const double* theta) const {
    SheetCorrection c = box;
    for (int k = 0; k < c.terms(); ++k) c.log_conductance[static_cast<std::size_t>(k)] = theta[k];
    return c;
  }
  double drive_V(const double* log_drive) const { return sensor.drive_voltage_V * std::exp(log_drive[0]); }
  std::vector<double> series_ohm(const double* series) const {
    std::vector<double> ohm(static_cast<std::size_t>(electrodes()));
    for (std::size_t e = 0; e < ohm.size(); ++e) ohm[e] = std::max(0.0, series_unit_ohm * series[e]);
    return ohm;
  }
};

/// One press's own unknowns, solved inside each evaluation (variable projection): its centre
/// (fitted only when unknown) and its log contact conductance.
struct PressFit {
  Vector2 centre_mm;
  double log_g = 0;
};

/// The presses' misfits (predicted − measured)/σ for one sensor (θ, shifts, R, E): the Green's
/// function of the corrected sheet on the slid mesh (on each press's block: its patch, or for a
/// press of unknown place the neighbourhood it may move in, with the electrodes; kept while θ,
/// the shifts and the blocks stay), then per press its own unknowns by a small damped
/// Gauss–Newton, warm-started. One per thread.
class Evaluator {
 public:
  /// `whole_sheet`: every column of the Green's function, for a search over the whole sheet.
  explicit Evaluator(const Presses& presses, bool whole_sheet = false) : p_(presses), whole_sheet_(whole_sheet) {}

  /// The sheet and electrodes of the next evaluations, the presses' blocks placed for `fits`.
  /// False when the electrodes cannot slide that far (Ceres then rejects the step).
  bool set_sheet(const double* theta, const double* shift, const std::vector<PressFit>& fits) {
    const std::vector<double> t(theta, theta + p_.box.terms()), d(shift, shift + p_.electrodes());
    const bool moved = !predictor_ || d != shift_;
    if (moved) {
      predictor_.reset();
      try {
        const bool none = std::all_of(d.begin(), d.end(), [](double s) { return s == 0; });
        mesh_ = none ? p_.base_mesh : slide_electrodes(p_.base_mesh, p_.sensor, d);
      } catch (const InvalidInput&) {
        return false;  // beyond the room to slide
      }
      integrator_ = std::make_unique<DiscContactIntegrator>(mesh_, p_.options.edge_mm, 3, p_.sensor.shape);
      integrate_known(fits);
      shift_ = d;
    }
    bool recentred = false;  // a press of unknown place gone far from its block's centre
    if (!moved && !whole_sheet_)
      for (std::size_t i = 0; i < fits.size(); ++i)
        if (p_.place_free[i] && (fits[i].centre_mm - block_centre_[i]).norm() > recentre_mm) {
          place_block(i, fits[i].centre_mm);
          recentred = true;
        }
    const bool changed = moved || recentred || t != theta_;  // the Green's function only then
    theta_ = t;
    if (changed) compute_green();
    return true;
  }

  /// Every press's residuals for series resistances R and drive E on the sheet set, each press's
  /// unknowns warm-started from `fits` and left there. A press of unknown place that ends near
  /// its block's edge has its block recentred and is fitted again (a few times at most), so that
  /// the blocks never bound a fit.
  bool residuals(const std::vector<double>& series_ohm, double E, std::vector<PressFit>& fits, double* residuals) {
    set_series_resistance(series_ohm);
    const int M = p_.readings();
    std::vector<std::size_t> walled;
    for (std::size_t i = 0; i < fits.size(); ++i) {
      double* r = residuals + static_cast<std::ptrdiff_t>(i) * M;
      if (!(p_.place_free[i] ? fit_free(E, i, fits[i], r) : fit_known(E, i, fits[i].log_g, r))) return false;
      if (near_edge(i, fits[i])) walled.push_back(i);
    }
    for (int round = 0; round < 4 && !walled.empty(); ++round) {
      for (const std::size_t i : walled) place_block(i, fits[i].centre_mm);
      compute_green();
      std::vector<std::size_t> again;
      for (const std::size_t i : walled) {
        if (!fit_free(E, i, fits[i], residuals + static_cast<std::ptrdiff_t>(i) * M)) return false;
        if (near_edge(i, fits[i])) again.push_back(i);
      }
      walled.swap(again);
    }
    return true;
  }

  /// The presses' residuals with their own unknowns held at `fits`, not fitted again: a Jacobian
  /// step's (the refit's first-order effect is then projected out, PressesCost).
  bool held_residuals(const std::vector<double>& series_ohm, double E, const std::vector<PressFit>& fits,
                      double* residuals) {
    set_series_resistance(series_ohm);
    const int M = p_.readings();
    for (std::size_t i = 0; i < fits.size(); ++i) {
      double* r = residuals + static_cast<std::ptrdiff_t>(i) * M;
      if (p_.place_free[i]) {
        if (!std::isfinite(press_cost(E, i, fits[i].centre_mm, fits[i].log_g, false, r))) return false;
        continue;
      }
      const DiscLoad& unit = unit_loads_[i];
      scaled_.resize(unit.local_S.size());
      for (std::size_t t = 0; t < scaled_.size(); ++t) scaled_[t] = std::exp(fits[i].log_g) * unit.local_S[t];
      predictor_->predict(unit.triangles, scaled_, E, frame_);
      for (int k = 0; k < M; ++k)
        r[k] = (frame_.data()[p_.measurements.frame_index[static_cast<std::size_t>(k)]] - p_.dV[i][k]) / p_.noise_V;
    }
    return std::all_of(residuals, residuals + p_.residual_count(), [](double r) { return std::isfinite(r); });
  }

  /// Per press, the last fit's Jacobian of its residuals in its own unknowns (M × 1: log g; M × 3:
  /// x, y, log g), at the point the residuals were left at.
  const std::vector<Matrix>& press_jacobians() const { return press_jacobians_; }

  void set_series_resistance(const std::vector<double>& ohm) {
    series_ohm_ = ohm;
    predictor_->set_series_resistance(ohm);
  }

  /// The frame, in units of the noise, of a disc of log conductance s at c: the starting search's.
  bool scaled_frame(const Vector2& c, double s, double E, Vector& out) {
    if (!chart_on_sheet(mesh_, p_.sensor.shape, c)) return false;
    load_.clear();
    integrator_->integrate({c.x(), c.y(), p_.options.prior_radius_mm, std::exp(s)}, load_);
    predictor_->predict(load_.triangles, load_.local_S, E, frame_);
    out.resize(p_.readings());
    for (int r = 0; r < p_.readings(); ++r)
      out[r] = frame_.data()[p_.measurements.frame_index[static_cast<std::size_t>(r)]] / p_.noise_V;
    return out.allFinite();
  }

 private:
  /// Each press of known place a held disc of unit conductance at its centre on the current
  /// mesh; each press's block of the Green's function (with the electrodes): a known press's
  /// patch, an unknown one's neighbourhood.
  void integrate_known(const std::vector<PressFit>& at) {
    dofs_ = number_electrode_dofs(mesh_);
    blocks_.assign(at.size(), {});
    block_centre_.assign(at.size(), Vector2::Zero());
    block_triangles_.assign(at.size(), {});
    unit_loads_.resize(at.size());
    for (std::size_t i = 0; i < at.size(); ++i) {
      unit_loads_[i].clear();  // integrate() appends
      if (p_.place_free[i]) {
        if (!whole_sheet_) place_block(i, at[i].centre_mm);
        continue;
      }
      const Vector2& c = at[i].centre_mm;
      integrator_->integrate({c.x(), c.y(), p_.options.prior_radius_mm, 1.0}, unit_loads_[i]);  // C is linear in g
      blocks_[i] = patch_dofs(unit_loads_[i]);
    }
  }

  /// The sorted dofs of a load's triangles.
  std::vector<int> patch_dofs(const DiscLoad& load) const {
    std::vector<int> dofs;
    for (Index t : load.triangles)
      for (int k = 0; k < 3; ++k) dofs.push_back(dofs_.dof_of_node[mesh_.triangles(t, k)]);
    std::sort(dofs.begin(), dofs.end());
    dofs.erase(std::unique(dofs.begin(), dofs.end()), dofs.end());
    return dofs;
  }

  /// Press i's block: the dofs a disc may touch within block_margin_mm of c.
  void place_block(std::size_t i, const Vector2& c) {
    DiscLoad reach;
    integrator_->integrate({c.x(), c.y(), p_.options.prior_radius_mm + block_margin_mm, 1.0}, reach);
    blocks_[i] = patch_dofs(reach);
    block_triangles_[i] = reach.triangles;
    block_centre_[i] = c;
  }

  /// The Green's function of the sheet θ on the mesh and blocks set, and its predictor.
  void compute_green() {
    predictor_.reset();
    const Vector conductance_S =
        p_.correction(theta_.data()).element_conductance_S(mesh_, p_.sensor.sheet_resistance_ohm_per_sq);
    green_ = whole_sheet_ ? dense_green_function(mesh_, conductance_S)
                          : blockwise_green_function(mesh_, conductance_S, blocks_);
    predictor_ = std::make_unique<FramePredictor>(mesh_, green_);
    if (!series_ohm_.empty()) predictor_->set_series_resistance(series_ohm_);
  }

  /// Whether press i, of unknown place, has come within a millimetre of its block's edge.
  bool near_edge(std::size_t i, const PressFit& fit) const {
    return !whole_sheet_ && p_.place_free[i] && (fit.centre_mm - block_centre_[i]).norm() > block_margin_mm - 1;
  }

  /// Whether the load lies in press i's block (always, with the whole sheet's Green's function).
  bool in_block(std::size_t i, const DiscLoad& load) const {
    if (whole_sheet_) return true;
    for (Index t : load.triangles)
      for (int k = 0; k < 3; ++k)
        if (!std::binary_search(blocks_[i].begin(), blocks_[i].end(), dofs_.dof_of_node[mesh_.triangles(t, k)]))
          return false;
    return true;
  }

  /// Gauss–Newton on s = log g (∂C/∂s = C); leaves the press's residuals in `residuals`.
  bool fit_known(double E, std::size_t i, double& s, double* residuals) {
    const DiscLoad& unit = unit_loads_[i];
    const int M = p_.readings();
    press_jacobians_.resize(p_.dV.size());
    Matrix& J = press_jacobians_[i];
    J.resize(M, 1);
    for (int iteration = 0; iteration < 40; ++iteration) {
      scaled_.resize(unit.local_S.size());
      for (std::size_t t = 0; t < scaled_.size(); ++t) scaled_[t] = std::exp(s) * unit.local_S[t];
      predictor_->predict(unit.triangles, scaled_, E, frame_);
      predictor_->derivative(unit.triangles, scaled_, d_frame_);
      double jr = 0, jj = 0;
      for (int r = 0; r < M; ++r) {
        const int at = p_.measurements.frame_index[static_cast<std::size_t>(r)];
        residuals[r] = (frame_.data()[at] - p_.dV[i][r]) / p_.noise_V;
        const double j = d_frame_.data()[at] / p_.noise_V;
        J(r, 0) = j;
        jr += j * residuals[r], jj += j * j;
      }
      if (!std::isfinite(jr) || !(jj > 0)) return false;
      const double step = std::clamp(-jr / jj, -2.0, 2.0);
      if (std::abs(step) < 1e-12) break;
      s += step;
    }
    return true;
  }

  /// The residuals of press i held at (c, s) into r, their cost ½|r|², and with `derivatives`
  /// the Jacobian in (x, y, s) into J_. Infinite off the sheet.
  double press_cost(double E, std::size_t i, const Vector2& c, double s, bool derivatives, double* r) {
    const bool on_sheet = whole_sheet_ ? chart_on_sheet(mesh_, p_.sensor.shape, c)
                                       : chart_on_sheet(mesh_, p_.sensor.shape, c, block_triangles_[i]);
    if (!on_sheet) return std::numeric_limits<double>::infinity();
    load_.clear();
    integrator_->integrate({c.x(), c.y(), p_.options.prior_radius_mm, std::exp(s)}, load_, derivatives);
    if (load_.triangles.empty() || !in_block(i, load_)) return std::numeric_limits<double>::infinity();
    predictor_->predict(load_.triangles, load_.local_S, E, frame_);
    const int M = p_.readings();
    double cost = 0;
    for (int k = 0; k < M; ++k) {
      r[k] = (frame_.data()[p_.measurements.frame_index[static_cast<std::size_t>(k)]] - p_.dV[i][k]) / p_.noise_V;
      cost += 0.5 * r[k] * r[k];
    }
    if (!derivatives) return std::isfinite(cost) ? cost : std::numeric_limits<double>::infinity();
    J_.resize(M, 3);
    for (int direction = 0; direction < 3; ++direction) {
      if (direction < 2) {
        scaled_.resize(load_.triangles.size());
        for (std::size_t t = 0; t < scaled_.size(); ++t)
          scaled_[t] = load_.d_local_S[t][static_cast<std::size_t>(direction)];
        predictor_->derivative(load_.triangles, scaled_, d_frame_);
      } else {
        predictor_->derivative(load_.triangles, load_.local_S, d_frame_);  // ∂C/∂s = C
      }
      for (int k = 0; k < M; ++k)
        J_(k, direction) = d_frame_.data()[p_.measurements.frame_index[static_cast<std::size_t>(k)]] / p_.noise_V;
    }
    return std::isfinite(cost) && J_.allFinite() ? cost : std::numeric_limits<double>::infinity();
  }

  /// Levenberg–Marquardt on (x, y, s) for a press of unknown place, from `fit`; leaves its
  /// residuals in `residuals`.
  bool fit_free(double E, std::size_t i, PressFit& fit, double* residuals) {
    const int M = p_.readings();
    trial_.resize(M);
    double cost = press_cost(E, i, fit.centre_mm, fit.log_g, true, residuals);
    if (!std::isfinite(cost)) return false;
    double mu = 1e-3;
    for (int iteration = 0; iteration < 50; ++iteration) {
      const Eigen::Map<const Vector> r(residuals, M);
      Eigen::Matrix3d A = J_.transpose() * J_;
      const Eigen::Vector3d g = J_.transpose() * r;
      A.diagonal() *= 1 + mu;
      const Eigen::Vector3d step = -A.ldlt().solve(g);
      const Vector2 c = fit.centre_mm + step.head<2>();
      const double s = fit.log_g + std::clamp(step[2], -2.0, 2.0);
      const double tried = press_cost(E, i, c, s, false, trial_.data());
      if (tried < cost) {
        fit.centre_mm = c, fit.log_g = s;
        mu = std::max(1e-9, mu / 4);
        cost = press_cost(E, i, c, s, true, residuals);
        if (step.head<2>().norm() < 1e-7 && std::abs(step[2]) < 1e-9) break;
      } else {
        mu *= 8;
        if (mu > 1e8) break;  // no step lowers the cost: a minimum to the precision there is
      }
    }
    press_jacobians_.resize(p_.dV.size());
    press_jacobians_[i] = J_;  // at the last accepted point, where the residuals are
    return std::isfinite(cost);
  }

  /// A press of unknown place moves within its block: block_margin_mm beyond its disc, the block
  /// recentred (a new Green's function) once the press is recentre_mm from the block's centre.
  static constexpr double block_margin_mm = 3, recentre_mm = 1;
  const Presses& p_;
  bool whole_sheet_;
  Mesh mesh_;  ///< the base mesh with the electrodes slid to shift_
  ElectrodeDofs dofs_;
  std::vector<double> shift_, theta_, series_ohm_;
  std::vector<Matrix> press_jacobians_;
  std::unique_ptr<DiscContactIntegrator> integrator_;
  std::vector<std::vector<int>> blocks_;             ///< per press, the sorted dofs of its block
  std::vector<Vector2> block_centre_;                ///< per press of unknown place, where its block is
  std::vector<std::vector<Index>> block_triangles_;  ///< and the triangles its block's disc touches
  std::vector<DiscLoad> unit_loads_;
  DiscLoad load_;
  std::vector<Eigen::Matrix3d> scaled_;
  Frame frame_, d_frame_;
  Matrix J_;
  Vector trial_;
  DenseGreenFunction green_;
  std::unique_ptr<FramePredictor> predictor_;
};

/// The presses' misfit as one Ceres residual block over the blocks θ, log E, R and the shifts,
/// its Jacobian by forward differences with the presses' own unknowns held at the point's fit,
/// each press's part then less its projection on that press's own Jacobian (variable projection
/// in Kaufman's form: the refit to first order, without refitting). The steps that change the sheet
/// or the electrodes need a Green's function each; they are shared between threads (each its own
/// Evaluator), the cheap ones (R, E) go first on the evaluator that holds the point's sheet.
class PressesCost : public ceres::CostFunction {
 public:
  PressesCost(const Presses& presses, std::vector<PressFit> start, int threads) : p_(presses), fits_(std::move(start)) {
    for (int t = 0; t < std::max(1, threads); ++t) evaluators_.push_back(std::make_unique<Evaluator>(presses));
    set_num_residuals(presses.residual_count());
    mutable_parameter_block_sizes()->assign({presses.box.terms(), 1, presses.electrodes(), presses.electrodes()});
  }

  const std::vector<PressFit>& fits() const { return fits_; }
  Evaluator& evaluator() const { return *evaluators_.front(); }

  bool Evaluate(double const* const* x, double* residuals, double** jacobians) const override {
    std::vector<PressFit> fits = fits_;
    Evaluator& base = *evaluators_.front();
    if (!base.set_sheet(x[0], x[3], fits_)) return false;
    if (!base.residuals(p_.series_ohm(x[2]), p_.drive_V(x[1]), fits, residuals)) return false;
    const int R = num_residuals();
    double cost = 0;
    for (int k = 0; k < R; ++k) cost += residuals[k] * residuals[k];
    if (cost < best_cost_) best_cost_ = cost, fits_ = fits;  // warm starts from the best point seen
    if (!jacobians) return true;

    struct Direction {
      int block, index;
      double step;
    };
    std::vector<Direction> directions;                          // the cheap ones first
    const std::array<double, 4> steps{1e-4, 1e-5, 1e-3, 1e-3};  // θ, log E, R/100 Ω, shift [mm]
    const bool fresh = sheet_jacobians_ < fresh_sheet_jacobians_;
    for (const int block : {1, 2, 0, 3}) {
      if (!jacobians[block]) continue;
      const auto size = static_cast<std::size_t>(num_residuals()) *
                        static_cast<std::size_t>(parameter_block_sizes()[static_cast<std::size_t>(block)]);
      const bool sheet = block == 0 || block == 3;
      if (sheet && !fresh) {  // the sheet's columns as last computed
        std::copy(kept_[static_cast<std::size_t>(block)].begin(), kept_[static_cast<std::size_t>(block)].end(),
                  jacobians[block]);
        continue;
      }
      if (sheet) kept_[static_cast<std::size_t>(block)].resize(size);
      for (int k = 0; k < parameter_block_sizes()[static_cast<std::size_t>(block)]; ++k)
        directions.push_back({block, k, steps[static_cast<std::size_t>(block)]});
    }
    // Each press's own Jacobian as an orthonormal basis (thin Q), for the projection below.
    const int M = p_.readings();
    std::vector<Matrix> own;
    for (const Matrix& J : base.press_jacobians())
      own.emplace_back(Eigen::HouseholderQR<Matrix>(J).householderQ() * Matrix::Identity(M, J.cols()));
    std::mutex taking;
    std::size_t front = 0, back = directions.size();
    bool failed = false;
    const auto work = [&](std::size_t which) {
      Evaluator& evaluator = *evaluators_[which];
      std::vector<double> moved(static_cast<std::size_t>(R));
      std::vector<std::vector<double>> blocks(4);
      for (std::size_t b = 0; b < 4; ++b) blocks[b].assign(x[b], x[b] + parameter_block_sizes()[b]);
      for (;;) {
        Direction d{};
        {
          const std::lock_guard<std::mutex> lock(taking);
          if (front == back || failed) return;
          d = which == 0 ? directions[front++] : directions[--back];  // the first takes the cheap end
        }
        std::vector<double>& value = blocks[static_cast<std::size_t>(d.block)];
        const auto stepped = [&](double step) {
          value[static_cast<std::size_t>(d.index)] += step;
          const bool ok = evaluator.set_sheet(blocks[0].data(), blocks[3].data(), fits) &&
                          evaluator.held_residuals(p_.series_ohm(blocks[2].data()), p_.drive_V(blocks[1].data()), fits,
                                                   moved.data());
          value[static_cast<std::size_t>(d.index)] -= step;
          return ok;
        };
        bool ok = stepped(d.step);
        if (!ok && d.block == 3 && stepped(-d.step)) ok = true, d.step = -d.step;  // a shift at its room's end
        if (!ok) {
          const std::lock_guard<std::mutex> lock(taking);
          failed = true;
          return;
        }
        // Each press's own refit, to first order: its column less its projection on the press's
        // own Jacobian (variable projection, Kaufman's Jacobian).
        Eigen::Map<Vector> column(moved.data(), R);
        column = (column - Eigen::Map<const Vector>(residuals, R)) / d.step;
        for (std::size_t i = 0; i < own.size(); ++i) {
          auto part = column.segment(static_cast<Index>(i) * M, M);
          part -= own[i] * (own[i].transpose() * part);
        }
        const int size = parameter_block_sizes()[static_cast<std::size_t>(d.block)];
        for (int k = 0; k < R; ++k) jacobians[d.block][static_cast<std::ptrdiff_t>(k) * size + d.index] = column[k];
      }
    };
    if (evaluators_.size() == 1) {
      work(0);
    } else {
      const SingleThreadedBlas one_each;
      std::vector<std::thread> threads;
      for (std::size_t t = 1; t < evaluators_.size(); ++t) threads.emplace_back(work, t);
      work(0);
      for (std::thread& t : threads) t.join();
    }
    if (failed) return false;
    if (fresh) {
      ++sheet_jacobians_;
      for (const int block : {0, 3})
        if (jacobians[block])
          std::copy(jacobians[block], jacobians[block] + kept_[static_cast<std::size_t>(block)].size(),
                    kept_[static_cast<std::size_t>(block)].begin());
    }
    return true;
  }

  /// The next Jacobian's columns in the sheet and the shifts computed afresh (for the covariance).
  void refresh_sheet_jacobian() const { fresh_sheet_jacobians_ = sheet_jacobians_ + 1; }

 private:
  const Presses& p_;
  /// Each of the sheet's and the shifts' columns costs a Green's function; after the first
  /// `fresh_sheet_jacobians_` they are kept (they change little once near the solution) and
  /// only the cheap ones (R, E) recomputed: Levenberg–Marquardt on the exact residuals still
  /// converges, a little more slowly.
  mutable int sheet_jacobians_ = 0, fresh_sheet_jacobians_ = 2;
  mutable std::array<std::vector<double>, 4> kept_;
  mutable std::vector<PressFit> fits_;
  mutable double best_cost_ = std::numeric_limits<double>::infinity();
  std::vector<std::unique_ptr<Evaluator>> evaluators_;
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

/// Where each press of unknown place starts: the point of a grid over the sheet (about 40 × 40
/// steps) whose disc, at one of a few conductances and scaled, comes nearest its frame; the
/// damped Gauss–Newton inside each evaluation refines it. The frames of the grid are computed once.
void start_free_presses(Evaluator& evaluator, const Presses& p, const Mesh& mesh, double E,
                        std::vector<PressFit>& fits) {
  const Eigen::AlignedBox2d box = chart_box(mesh, p.sensor.shape);
  const double step_mm = std::max(box.sizes().x(), box.sizes().y()) / 40;
  std::vector<PressFit> candidates;
  std::vector<Vector> frames;
  Vector frame;
  const double log_g0 = std::log(p.sensor.contact.conductance_S_per_mm2(0.1));
  const int columns = static_cast<int>(std::ceil(box.sizes().x() / step_mm));
  const int rows = static_cast<int>(std::ceil(box.sizes().y() / step_mm));
  for (int j = 0; j < rows; ++j)
    for (int i = 0; i < columns; ++i) {
      const Vector2 c = box.min() + step_mm * Vector2(i + 0.5, j + 0.5);
      for (const double ds : {-3.0, -1.5, 0.0, 1.5, 3.0})
        if (evaluator.scaled_frame(c, log_g0 + ds, E, frame)) {
          candidates.push_back(PressFit{c, log_g0 + ds});
          frames.emplace_back(frame / std::max(frame.norm(), 1e-300));
        }
    }
  if (candidates.empty()) throw SolverError("sensor calibration: no point of the sheet to start an unknown press at");
  for (std::size_t i = 0; i < fits.size(); ++i) {
    if (!p.place_free[i]) continue;
    const Vector d = p.dV[i] / p.noise_V;
    double best = -std::numeric_limits<double>::infinity();
    for (std::size_t k = 0; k < candidates.size(); ++k) {
      const double cosine = frames[k].dot(d);  // the best scale's fit: |d|² − (f̂·d)²
      if (cosine > best) best = cosine, fits[i] = candidates[k];
    }
  }
}

/// The ninths of the sheet's chart box (a 3 × 3 grid, named "lower left" … "upper right") whose
/// centre is on the sheet and that hold none of the presses' centres: a degenerate set (all presses
/// in one corner) leaves the field there to the cubic's extrapolation.
std::vector<std::string> uncovered_thirds(const Mesh& mesh, const Shape& shape, const std::vector<Vector2>& centres) {
  const Eigen::AlignedBox2d box = chart_box(mesh, shape);
  const Vector2 size = box.sizes() / 3;
  const char* rows[] = {"lower", "middle", "upper"};
  const char* columns[] = {"left", "middle", "right"};
  std::vector<std::string> empty;
  for (int j = 0; j < 3; ++j)
    for (int i = 0; i < 3; ++i) {
      const Vector2 low = box.min() + Vector2(i * size.x(), j * size.y()), high = low + size;
      if (!chart_on_sheet(mesh, shape, (low + high) / 2)) continue;
      const bool hit = std::any_of(centres.begin(), centres.end(), [&](const Vector2& c) {
        return c.x() >= low.x() && c.x() <= high.x() && c.y() >= low.y() && c.y() <= high.y();
      });
      if (!hit) {
        char line[160];
        std::snprintf(line, sizeof line, "%s %s ninth (x %.0f to %.0f mm, y %.0f to %.0f mm)",
                      j == 1 && i == 1 ? "" : rows[j], j == 1 && i == 1 ? "centre" : columns[i], low.x(), high.x(),
                      low.y(), high.y());
        empty.emplace_back(line[0] == ' ' ? line + 1 : line);
      }
    }
  return empty;
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
  if (dV.size() < static_cast<std::size_t>(least_calibration_presses))
    throw InvalidInput("sensor calibration: " + std::to_string(dV.size()) + " presses; at least " +
                       std::to_string(least_calibration_presses) + " are needed");
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
  Presses presses{sensor, fit_mesh, measurements, dV,
                  {},     resolved, noise_V,      SheetCorrection::identity_over(fit_mesh, options.sheet_terms)};
  std::vector<PressFit> start(dV.size());
  for (std::size_t i = 0; i < dV.size(); ++i) {
    const Vector2& c = centres_mm[i];
    const bool free = !std::isfinite(c.x()) || !std::isfinite(c.y());
    presses.place_free.push_back(free);
    presses.any_free = presses.any_free || free;
    if (!free && !chart_on_sheet(fit_mesh, sensor.shape, c))
      throw InvalidInput("sensor calibration: a press centre (" + std::to_string(c.x()) + ", " + std::to_string(c.y()) +
                         ") mm is off the sheet");
    start[i] = {free ? Vector2::Zero() : c, std::log(sensor.contact.conductance_S_per_mm2(0.1))};
  }

  Blocks x;
  x.theta.assign(static_cast<std::size_t>(options.sheet_terms), 0.0);
  x.series.assign(static_cast<std::size_t>(N), 0.0);
  x.shift_mm.assign(static_cast<std::size_t>(N), 0.0);
  for (std::size_t e = 0; e < sensor.series_resistance_ohm.size(); ++e)
    x.series[e] = sensor.series_resistance_ohm[e] / series_unit_ohm;
  const std::vector<double> series_prior_mean = x.series;
  SensorCalibration result;
  result.presses = static_cast<int>(dV.size());
  if (presses.any_free) {
    Evaluator search(presses, true);
    search.set_sheet(x.theta.data(), x.shift_mm.data(), start);
    search.set_series_resistance(presses.series_ohm(x.series.data()));
    if (progress) progress("sensor calibration: placing the presses of unknown place");
    start_free_presses(search, presses, fit_mesh, sensor.drive_voltage_V, start);
  }
  auto* cost = new PressesCost(presses, start, thread_count());
  std::vector<double> residuals(static_cast<std::size_t>(presses.residual_count()));
  const double* values[] = {x.theta.data(), x.log_drive.data(), x.series.data(), x.shift_mm.data()};
  if (!cost->Evaluate(values, residuals.data(), nullptr))
    throw SolverError("sensor calibration: the nominal sensor's fit failed");
  result.rms_misfit_nominal_V = rms_V(residuals, noise_V);

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
  Progress news(progress, presses.residual_count(), noise_V);
  if (progress) solver.callbacks.push_back(&news);
  ceres::Solver::Summary summary;
  ceres::Solve(solver, &problem, &summary);
  if (!summary.IsSolutionUsable()) throw SolverError("sensor calibration: " + summary.message);

  result.correction = presses.correction(x.theta.data());
  result.drive_voltage_V = presses.drive_V(x.log_drive.data());
  result.series_resistance_ohm = presses.series_ohm(x.series.data());
  result.electrode_shift_mm = x.shift_mm;
  if (!cost->Evaluate(values, residuals.data(), nullptr))
    throw SolverError("sensor calibration: the calibrated sensor's fit failed");
  for (std::size_t i = 0; i < dV.size(); ++i)
    result.centres_mm.push_back(cost->fits()[i].centre_mm), result.place_fitted.push_back(presses.place_free[i]);
  result.rms_misfit_corrected_V = rms_V(residuals, noise_V);
  const double chi2 = (result.rms_misfit_corrected_V / noise_V) * (result.rms_misfit_corrected_V / noise_V);
  result.chi2_per_reading = chi2;

  // Identifiability: the posterior covariance (JᵀJ + prior)⁻¹ in the blocks' units, inflated by
  // the misfit per reading when the model misfits beyond the noise, and the model's own error.
  cost->refresh_sheet_jacobian();
  const Matrix J = data_jacobian(problem, data, free_blocks);
  std::vector<double> prior_std, model_std;
  std::vector<std::pair<std::string, double>> named;  // name, unit factor (block unit → reported unit)
  const char* theta_names[] = {"u", "v", "u^2", "uv", "v^2", "u^3", "u^2 v", "u v^2", "v^3"};
  for (int k = 0; k < options.sheet_terms; ++k) {
    named.emplace_back(std::string("sheet log-conductance ") + theta_names[k], 1.0);
    prior_std.push_back(theta_prior_std);
    model_std.push_back(theta_model_std);
  }
  if (options.fit_drive_voltage) {
    named.emplace_back("drive_voltage_V", result.drive_voltage_V);
    prior_std.push_back(log_drive_prior_std);
    model_std.push_back(log_drive_model_std);
  }
  if (options.fit_series_resistance)
    for (int e = 0; e < N; ++e) {
      named.emplace_back("series_resistance_ohm[" + std::to_string(e) + "]", series_unit_ohm);
      prior_std.push_back(series_prior_std);
      model_std.push_back(series_model_std);
    }
  if (fit_positions)
    for (int e = 0; e < N; ++e) {
      named.emplace_back("electrode_shift_mm[" + std::to_string(e) + "]", 1.0);
      prior_std.push_back(shift_prior_std_mm);
      model_std.push_back(shift_model_std_mm);
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
    const double statistical = std::sqrt(covariance(static_cast<Index>(k), static_cast<Index>(k)));
    p.std = std::hypot(statistical, model_std[k]) * named[k].second;
    p.prior_std = prior_std[k] * named[k].second;
    p.determined = statistical < 0.5 * prior_std[k];  // the presses, not the prior, set it
    result.parameters.push_back(p);
  }

  // Doubts a user must hear about.
  for (const std::string& empty : uncovered_thirds(fit_mesh, sensor.shape, result.centres_mm))
    result.warnings.push_back("no press in the sheet's " + empty +
                              ": the sheet's field there is the fit's extrapolation; press there too");
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
    centres.push_back(place_known(presses[f][0]) ? press_chart_mm(sensor.shape, presses[f][0])
                                                 : Vector2::Constant(std::numeric_limits<double>::quiet_NaN()));
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
