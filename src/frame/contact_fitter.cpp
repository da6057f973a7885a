#include "emit/frame/contact_fitter.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include <ceres/ceres.h>

#include "emit/core/errors.hpp"
#include "emit/mesh/sheet_chart.hpp"
#include "emit/sensor/adc.hpp"
#include "emit/sensor/surface.hpp"

namespace emit {

void FitOptions::validate() const {
  if (max_contacts < 1) throw InvalidInput("fit: max_contacts must be at least 1");
  if (!(edge_mm >= 0)) throw InvalidInput("fit: edge_mm must not be negative");
  if (!(prior_radius_mm >= 0)) throw InvalidInput("fit: prior_radius_mm must not be negative");
}

namespace {

constexpr int disc_parameters = 4;  // x [mm], y [mm], log r [log mm], log g [log S/mm²]

std::array<double, disc_parameters> to_parameters(const Disc& d) {
  return {d.x_mm, d.y_mm, std::log(d.radius_mm), std::log(d.conductance_S_per_mm2)};
}

Disc to_disc(const double* p) { return {p[0], p[1], std::exp(p[2]), std::exp(p[3])}; }

}  // namespace

/// Ceres's view of the fit: residuals (predicted − measured)/σ for all discs at once, with the
/// analytic Jacobian (disc_contact.hpp's ∂C/∂(x, y, r), ∂C/∂log g = C, frame_predictor.hpp's
/// derivative).
class FrameMisfit : public ceres::CostFunction {
 public:
  FrameMisfit(ContactFitter& fitter, const Vector& dV, int discs) : fitter_(fitter), dV_(dV), discs_(discs) {
    for (int i = 0; i < discs; ++i) mutable_parameter_block_sizes()->push_back(disc_parameters);
    set_num_residuals(fitter.shared_.measurements_.size());
  }

  bool Evaluate(double const* const* parameters, double* residuals, double** jacobians) const override {
    ContactFitter& f = fitter_;
    const FitPrecompute& shared = f.shared_;
    f.load_.clear();
    ranges_.clear();
    for (int i = 0; i < discs_; ++i) {
      const std::size_t begin = f.load_.triangles.size();
      shared.integrator_.integrate(to_disc(parameters[i]), f.load_, jacobians != nullptr);
      ranges_.emplace_back(begin, f.load_.triangles.size());
    }
    f.predictor_.predict(f.load_.triangles, f.load_.local_S, shared.sensor_.drive_voltage_V, f.frame_);
    const MeasurementSet& m = shared.measurements_;
    bool finite = true;
    for (int r = 0; r < m.size(); ++r) {
      residuals[r] = (f.frame_.data()[m.frame_index[r]] - dV_[r]) / shared.noise_V_;
      finite = finite && std::isfinite(residuals[r]);
    }
    if (!finite) return false;  // a step too far: Ceres shrinks it
    if (!jacobians) return true;
    for (int i = 0; i < discs_; ++i) {
      if (!jacobians[i]) continue;
      for (int j = 0; j < disc_parameters; ++j) {
        if (j == 2) {  // the radius is held: Ceres ignores the column, so spare its solve
          for (int r = 0; r < m.size(); ++r) jacobians[i][r * disc_parameters + j] = 0;
          continue;
        }
        direction_.assign(f.load_.triangles.size(), Eigen::Matrix3d::Zero());
        for (std::size_t t = ranges_[i].first; t < ranges_[i].second; ++t)
          direction_[t] = j == 3 ? f.load_.local_S[t] : f.load_.d_local_S[t][j];
        f.predictor_.derivative(f.load_.triangles, direction_, d_frame_);
        for (int r = 0; r < m.size(); ++r)
          jacobians[i][r * disc_parameters + j] = d_frame_.data()[m.frame_index[r]] / shared.noise_V_;
      }
    }
    return true;
  }

 private:
  ContactFitter& fitter_;
  const Vector& dV_;
  int discs_;
  mutable std::vector<std::pair<std::size_t, std::size_t>> ranges_;
  mutable std::vector<Eigen::Matrix3d> direction_;
  mutable Frame d_frame_;
};

FitOptions resolved_fit_options(FitOptions o, const Sensor& sensor, const Mesh& mesh) {
  o.validate();
  if (o.edge_mm == 0) o.edge_mm = sensor.mesh.element_size_mm / 4;
  if (o.prior_radius_mm == 0) o.prior_radius_mm = 2 * sensor.mesh.element_size_mm;
  const Vector2 extent = chart_box(mesh, sensor.shape).sizes();
  if (extent.minCoeff() <= 2 * sensor.mesh.element_size_mm)
    throw InvalidInput("fit: the sheet is too small for its mesh");
  return o;
}

FitPrecompute::FitPrecompute(const Sensor& sensor, const Mesh& mesh, const DenseGreenFunction& green,
                             const MeasurementSet& measurements, FitOptions options)
    : sensor_(sensor),
      mesh_(mesh),
      green_(green),
      measurements_(measurements),
      chart_box_(chart_box(mesh, sensor.shape)),
      options_(resolved_fit_options(options, sensor, mesh)),
      integrator_(mesh, options_.edge_mm, 3, sensor.shape),
      noise_V_(reading_noise_V(sensor.adc)) {
  build_atoms();
}

ContactFitter::ContactFitter(const FitPrecompute& shared) : shared_(shared), predictor_(shared.mesh_, shared.green_) {
  predictor_.set_series_resistance(shared.sensor_.series_resistance_ohm);
}

ContactFitter::ContactFitter(const Sensor& sensor, const Mesh& mesh, const DenseGreenFunction& green,
                             const MeasurementSet& measurements, FitOptions options)
    : owned_(std::make_unique<const FitPrecompute>(sensor, mesh, green, measurements, options)),
      shared_(*owned_),
      predictor_(mesh, green) {
  predictor_.set_series_resistance(sensor.series_resistance_ohm);
}

/// The frames of a disc at the contact law's conductance at 0.1 N/mm² on a grid over the sheet
/// (in units of σ), and their Gram matrix. While the contact's resistance dwarfs the sheet's, each
/// contact draws a current of its own: a frame with several is close to a positive sum of atoms.
void FitPrecompute::build_atoms() {
  const double spacing = 1.5 * options_.prior_radius_mm;  // finer than the plausible separation
  const double g = sensor_.contact.conductance_S_per_mm2(0.1);
  ContactFitter workspace(*this);  // its predictor (the atoms are not built yet: it does not fit)
  std::vector<Vector> columns;
  // The grid's coordinates are accumulated steps, as the fits (and their recorded results) have
  // always seen them; a rounding at the far edge can only add or drop a point off the mesh.
  // NOLINTNEXTLINE(clang-analyzer-security.FloatLoopCounter)
  for (double y = chart_box_.min().y() + spacing / 2; y < chart_box_.max().y(); y += spacing)
    // NOLINTNEXTLINE(clang-analyzer-security.FloatLoopCounter)
    for (double x = chart_box_.min().x() + spacing / 2; x < chart_box_.max().x(); x += spacing) {
      const Disc d{x, y, options_.prior_radius_mm, g};
      if (!chart_on_sheet(mesh_, sensor_.shape, Vector2(x, y))) continue;
      Vector column;
      workspace.misfit({d}, Vector::Zero(measurements_.size()), column);
      columns.emplace_back(column / noise_V_);
      atom_discs_.push_back(d);
    }
  atoms_.resize(measurements_.size(), static_cast<Index>(columns.size()));
  for (std::size_t a = 0; a < columns.size(); ++a) atoms_.col(static_cast<Index>(a)) = columns[a];
  atom_gram_ = atoms_.transpose() * atoms_;
}

/// The set of `count` atoms, pairwise at least the plausible separation apart, whose positive
/// combination best explains `target` (σ units): a global search for the starts of a fit of that
/// many contacts, where seeds from linear images mislead (their peaks sit by the electrodes, and
/// one disc fitted to two presses settles between them). Greedy, each atom added the one that
/// explains most with all weights positive, then each member swapped for any atom that explains
/// more (the greedy first choice is often between two presses). The explained sum of squares of
/// a set S is bᵀ_S G_S⁻¹ b_S, G the atoms' Gram matrix: a solve of at most max_contacts unknowns.
/// \return false if no such set has all weights positive.
bool FitPrecompute::best_atom_set(const Vector& target, int count, std::vector<Disc>& set) const {
  const Vector b = atoms_.transpose() * target;
  const double min_separation = plausible_separation_mm();
  const auto atoms = static_cast<Index>(atom_discs_.size());
  const auto apart = [&](Index i, Index j) {
    const Disc &p = atom_discs_[static_cast<std::size_t>(i)], &q = atom_discs_[static_cast<std::size_t>(j)];
    return separation_mm(p, q) >= min_separation;
  };
  // The explained sum of squares of a set, and its weights; −1 if a weight is not positive.
  const auto explained_by = [&](const std::vector<Index>& members, Vector& w) {
    const auto k = static_cast<Index>(members.size());
    Matrix G(k, k);
    Vector bs(k);
    for (Index r = 0; r < k; ++r) {
      bs[r] = b[members[static_cast<std::size_t>(r)]];
      for (Index c = 0; c < k; ++c)
        G(r, c) = atom_gram_(members[static_cast<std::size_t>(r)], members[static_cast<std::size_t>(c)]);
    }
    const Eigen::LDLT<Matrix> ldlt(G);
    if (ldlt.info() != Eigen::Success || !(ldlt.vectorD().array() > 1e-12 * G.diagonal().maxCoeff()).all()) return -1.0;
    w = ldlt.solve(bs);
    if (!(w.array() > 0).all()) return -1.0;
    return w.dot(bs);
  };
  std::vector<Index> members;
  Vector w;
  // Best replacement of slot `slot` (or a new member at the end), keeping the others.
  const auto best_for_slot = [&](std::size_t slot, double current) {
    double best = current;
    Index best_atom = -1;
    std::vector<Index> trial = members;
    if (slot == trial.size()) trial.push_back(-1);
    for (Index a = 0; a < atoms; ++a) {
      bool ok = true;
      for (std::size_t m = 0; m < trial.size() && ok; ++m) ok = m == slot || (trial[m] != a && apart(trial[m], a));
      if (!ok) continue;
      trial[slot] = a;
      const double e = explained_by(trial, w);
      if (e > best) best = e, best_atom = a;
    }
    if (best_atom < 0) return current;
    if (slot == members.size()) members.push_back(best_atom);
    else members[slot] = best_atom;
    return best;
  };
  double explained = 0;
  for (int k = 0; k < count; ++k) {
    const std::size_t before = members.size();
    explained = best_for_slot(members.size(), explained);
    if (members.size() == before) return false;  // no further atom with all weights positive
  }
  for (int sweep = 0; sweep < 2; ++sweep)
    for (std::size_t slot = 0; slot < members.size(); ++slot) explained = best_for_slot(slot, explained);
  if (explained_by(members, w) <= 0) return false;
  set.clear();
  for (std::size_t m = 0; m < members.size(); ++m) {
    const Disc& d = atom_discs_[static_cast<std::size_t>(members[m])];
    // In the current-source regime a disc's frame scales with its conductance.
    set.push_back({d.x_mm, d.y_mm, d.radius_mm, d.conductance_S_per_mm2 * w[static_cast<Index>(m)]});
  }
  return true;
}

Frame ContactFitter::predict(const std::vector<Disc>& discs) {
  load_.clear();
  for (const Disc& d : discs) shared_.integrator_.integrate(d, load_);
  predictor_.predict(load_.triangles, load_.local_S, shared_.sensor_.drive_voltage_V, frame_);
  return frame_;
}

void ContactFitter::misfit(const std::vector<Disc>& discs, const Vector& dV, Vector& out) {
  predict(discs);
  const MeasurementSet& m = shared_.measurements_;
  out.resize(m.size());
  for (int i = 0; i < m.size(); ++i) out[i] = frame_.data()[m.frame_index[i]] - dV[i];
}

/// The distance between two discs' centres on the sheet (in 3D: a chord on a curved one).
double FitPrecompute::separation_mm(const Disc& a, const Disc& b) const {
  return (surface_point_mm(sensor_.shape, {a.x_mm, a.y_mm}) - surface_point_mm(sensor_.shape, {b.x_mm, b.y_mm})).norm();
}

Disc FitPrecompute::clamp_seed(Disc seed) const {
  seed.x_mm = std::clamp(seed.x_mm, chart_box_.min().x(), chart_box_.max().x());
  seed.y_mm = is_sleeve(sensor_.shape) ? wrapped_chart_mm(sensor_.shape, {seed.x_mm, seed.y_mm}).y()
                                       : std::clamp(seed.y_mm, chart_box_.min().y(), chart_box_.max().y());
  seed.radius_mm = options_.prior_radius_mm;
  const double g = sensor_.contact.conductance_S_per_mm2(0.1);
  seed.conductance_S_per_mm2 =
      seed.conductance_S_per_mm2 > 0 ? std::clamp(seed.conductance_S_per_mm2, g * std::exp(-13), g * std::exp(13)) : g;
  return seed;
}

/// A set of discs is presses only if every disc is on the sheet (one pushed off it is the
/// optimiser using it as a fudge) and none is beside another: two small discs side by side are
/// one large press, modelled by two (the held radius is smaller than most presses).
bool FitPrecompute::plausible_set(const std::vector<Disc>& discs) const {
  for (std::size_t i = 0; i < discs.size(); ++i) {
    if (!chart_on_sheet(mesh_, sensor_.shape, Vector2(discs[i].x_mm, discs[i].y_mm))) return false;
    for (std::size_t j = 0; j < i; ++j)
      if (separation_mm(discs[i], discs[j]) < plausible_separation_mm()) return false;
  }
  return true;
}

/// The misfit is the noise's (within a bound on χ²), or what it has beyond the noise is the
/// model's error: a small fraction of the frame's energy, as a press's shape departs from a held
/// disc in proportion to its frame. A missed press leaves a larger fraction (FitOptions).
bool FitPrecompute::explained(double misfit_sq, const Vector& dV) const {
  const double noise_sq = noise_V_ * noise_V_ * measurements_.size();
  if (misfit_sq <= ContactFitter::noise_chi2_per_measurement * noise_sq) return true;
  const double fraction = ContactFitter::model_error_rms_fraction;
  return misfit_sq - noise_sq <= fraction * fraction * dV.squaredNorm();
}

/// 1σ of each parameter from the Gauss–Newton covariance (JᵀJ)⁻¹ at the solution (residuals are
/// in units of σ), scaled up by the misfit per degree of freedom where the model misfits more than
/// the noise. Computed here from the analytic Jacobian rather than by ceres::Covariance, whose
/// Eigen temporaries cross the library boundary (and an ASan build's allocator with them).
void ContactFitter::parameter_std(const Vector& dV, std::vector<std::array<double, 4>>& parameters, double chi2) {
  const int k = static_cast<int>(parameters.size()), M = shared_.measurements_.size();
  const FrameMisfit cost(*this, dV, k);
  Vector residuals(M);
  std::vector<Eigen::Matrix<double, Eigen::Dynamic, disc_parameters, Eigen::RowMajor>>
  blocks(k, decltype(blocks)::value_type(M, disc_parameters));
  std::vector<const double*> values;
  std::vector<double*> jacobians;
  for (int i = 0; i < k; ++i) values.push_back(parameters[i].data()), jacobians.push_back(blocks[i].data());
  if (!cost.Evaluate(values.data(), residuals.data(), jacobians.data())) return;
  std::vector<int> free;  // the radius is held
  for (int i = 0; i < k; ++i)
    for (int j = 0; j < disc_parameters; ++j)
      if (j != 2) free.push_back(disc_parameters * i + j);
  Matrix J(M, static_cast<Index>(free.size()));
  for (std::size_t c = 0; c < free.size(); ++c)
    J.col(static_cast<Index>(c)) = blocks[free[c] / disc_parameters].col(free[c] % disc_parameters);
  const Matrix covariance = (J.transpose() * J).completeOrthogonalDecomposition().pseudoInverse();
  const double scale = std::max(1.0, chi2 / std::max<double>(1, M - static_cast<double>(free.size())));
  for (std::size_t c = 0; c < free.size(); ++c)
    covariance_std_[static_cast<std::size_t>(free[c])] =
        std::sqrt(std::max(0.0, covariance(static_cast<Index>(c), static_cast<Index>(c)) * scale));
}

/// Levenberg–Marquardt on all discs at once. \return the misfit's sum of squares [V²].
double ContactFitter::fit_discs(const Vector& dV, std::vector<Disc>& discs) {
  const int k = static_cast<int>(discs.size());
  std::vector<std::array<double, disc_parameters>> parameters;
  parameters.reserve(discs.size());
  for (const Disc& d : discs) parameters.push_back(to_parameters(d));
  ceres::Problem problem;
  std::vector<double*> blocks;
  blocks.reserve(parameters.size());
  for (auto& p : parameters) blocks.push_back(p.data());
  problem.AddResidualBlock(new FrameMisfit(*this, dV, k), nullptr, blocks);
  for (double* p : blocks) {
    problem.SetParameterLowerBound(p, 0, shared_.chart_box_.min().x());
    problem.SetParameterUpperBound(p, 0, shared_.chart_box_.max().x());
    if (!is_sleeve(shared_.sensor_.shape)) {  // around a sleeve the chart is periodic: no bound
      problem.SetParameterLowerBound(p, 1, shared_.chart_box_.min().y());
      problem.SetParameterUpperBound(p, 1, shared_.chart_box_.max().y());
    }
    // g within six decades of the contact law's at 0.1 N/mm²: keeps exp(log g) finite.
    const double log_g = std::log(shared_.sensor_.contact.conductance_S_per_mm2(0.1));
    problem.SetParameterLowerBound(p, 3, log_g - 14);
    problem.SetParameterUpperBound(p, 3, log_g + 14);
    problem.SetManifold(p, new ceres::SubsetManifold(disc_parameters, {2}));  // the radius is held
  }
  ceres::Solver::Options solver;
  solver.linear_solver_type = ceres::DENSE_QR;
  solver.max_num_iterations = max_iterations;
  solver.logging_type = ceres::SILENT;
  solver.function_tolerance = 1e-10;
  solver.parameter_tolerance = 1e-10;
  ceres::Solver::Summary summary;
  ceres::Solve(solver, &problem, &summary);
  result_.evaluations += summary.num_residual_evaluations;

  for (int i = 0; i < k; ++i) {
    discs[i] = to_disc(parameters[i].data());
    discs[i].y_mm = wrapped_chart_mm(shared_.sensor_.shape, {discs[i].x_mm, discs[i].y_mm}).y();
  }
  return 2 * summary.final_cost * shared_.noise_V_ * shared_.noise_V_;
}

/// Two starts for one more contact at `seed`: the fitted discs as they are plus the seed, and a
/// split one, the disc nearest the seed mirrored away from it. A single disc fitted to two presses
/// settles between them, nearer the stronger; kept there, it leads Levenberg–Marquardt into a
/// local minimum (a strong disc between the presses, a weak one beyond), and a seed at either press
/// sits beside it. Mirrored, the pair starts near both presses.
void ContactFitter::add_starts(const std::vector<Disc>& discs, const Disc& seed,
                               std::vector<std::vector<Disc>>& starts) const {
  const Disc added = shared_.clamp_seed(seed);
  starts.push_back(discs);
  starts.back().push_back(added);
  const auto distance = [&](const Disc& d) { return shared_.separation_mm(d, added); };
  const auto nearest = std::min_element(discs.begin(), discs.end(),
                                        [&](const Disc& a, const Disc& b) { return distance(a) < distance(b); });
  // Mirrored less than the plausible separation apart, the pair would be one press anyway.
  if (2 * distance(*nearest) < shared_.plausible_separation_mm()) return;
  std::vector<Disc> split = starts.back();
  Disc& moved = split[static_cast<std::size_t>(nearest - discs.begin())];
  moved = shared_.clamp_seed(
      {2 * moved.x_mm - added.x_mm, 2 * moved.y_mm - added.y_mm, moved.radius_mm, moved.conductance_S_per_mm2});
  starts.push_back(std::move(split));
}

/// Levenberg–Marquardt from each start. \return whether one gave a plausible fit; `best` and
/// `best_sq` then hold the lowest misfit's.
bool ContactFitter::fit_best_start(const Vector& dV, std::vector<std::vector<Disc>>& starts, std::vector<Disc>& best,
                                   double& best_sq) {
  bool found = false;
  for (std::vector<Disc>& start : starts) {
    if (!shared_.plausible_set(start)) continue;  // a seed beside a contact: not worth a fit
    const double sq = fit_discs(dV, start);
    if (shared_.plausible_set(start) && (!found || sq < best_sq)) best = std::move(start), best_sq = sq, found = true;
  }
  return found;
}

/// The result of a fit ending at `discs`: uncertainties, pressures, strongest first.
void ContactFitter::finish(const Vector& dV, const std::vector<Disc>& discs, double misfit_sq) {
  std::vector<std::array<double, disc_parameters>> parameters;
  parameters.reserve(discs.size());
  for (const Disc& d : discs) parameters.push_back(to_parameters(d));
  covariance_std_.assign(static_cast<std::size_t>(disc_parameters * discs.size()), 0.0);
  parameter_std(dV, parameters, misfit_sq / (shared_.noise_V_ * shared_.noise_V_));
  result_.rms_misfit_V = std::sqrt(misfit_sq / shared_.measurements_.size());
  for (std::size_t i = 0; i < discs.size(); ++i) {
    const double* s = covariance_std_.data() + disc_parameters * i;
    // r = e^ρ: σ_r = r σ_ρ; σ_g/g = σ_log g.
    const double pressure = shared_.sensor_.contact.pressure_N_per_mm2(discs[i].conductance_S_per_mm2);
    result_.contacts.push_back({discs[i], s[0], s[1], discs[i].radius_mm * s[2], s[3], pressure,
                                pressure * s[3] / std::abs(shared_.sensor_.contact.gamma)});
  }
  std::sort(result_.contacts.begin(), result_.contacts.end(), [](const FittedContact& a, const FittedContact& b) {
    return a.disc.conductance_S_per_mm2 * a.disc.radius_mm * a.disc.radius_mm >
           b.disc.conductance_S_per_mm2 * b.disc.radius_mm * b.disc.radius_mm;
  });
}

/// Tracking several contacts follows fingers that moved less than the separation that tells two
/// presses apart (a sliding finger moves ~0.5 mm a frame). A disc of a set that went further was
/// pulled to another press, or into a local minimum between presses that still explains the frame
/// about as well (two discs 3–5 mm off two strong presses on the 60 mm sheet: χ²/M 3.2, the right
/// pair's ~3); the cold fit, with its global search for the pair, decides there. One disc has no
/// such minima: wherever it went, if it explains the frame the cold fit would agree.
bool FitPrecompute::jumped(const std::vector<Disc>& previous, const std::vector<Disc>& discs) const {
  if (discs.size() < 2) return false;
  for (std::size_t i = 0; i < discs.size(); ++i)
    if (separation_mm(discs[i], previous[i]) > plausible_separation_mm()) return true;
  return false;
}

const FitResult& ContactFitter::track(const Vector& dV, const std::vector<Disc>& previous) {
  if (dV.size() != shared_.measurements_.size()) throw InvalidInput("fit: one value per measurement is needed");
  result_ = {};
  if (previous.empty()) return result_;
  std::vector<Disc> discs = previous;
  const double misfit_sq = fit_discs(dV, discs);
  if (!shared_.explained(misfit_sq, dV) || !shared_.plausible_set(discs) || shared_.jumped(previous, discs))
    return result_;
  // A lifted finger: its disc fades to nothing the readings can see.
  for (const Disc& d : discs) {
    zeros_.setZero(shared_.measurements_.size());
    misfit({d}, zeros_, residual_);
    if (residual_.cwiseAbs().maxCoeff() < 5 * shared_.noise_V_) return result_;
  }
  result_.tracked = true;
  finish(dV, discs, misfit_sq);
  return result_;
}

const FitResult& ContactFitter::fit(const Vector& dV, const std::vector<Disc>& seeds,
                                    const std::function<bool(const Vector&, Disc&)>& residual_peak) {
  if (dV.size() != shared_.measurements_.size()) throw InvalidInput("fit: one value per measurement is needed");
  result_ = {};
  // No contact at all already explains the frame (the rule every further contact answers to):
  // the linear image of noise always has a peak to seed from, and a faint disc at the border
  // would "explain" it.
  if (shared_.explained(dV.squaredNorm(), dV)) {
    result_.rms_misfit_V = std::sqrt(dV.squaredNorm() / static_cast<double>(shared_.measurements_.size()));
    return result_;
  }
  if (seeds.empty()) return result_;
  std::vector<Disc> discs{shared_.clamp_seed(seeds[0])};
  double misfit_sq = fit_discs(dV, discs);
  std::size_t next_seed = 1;
  Vector residual;
  // The starts for one more contact, all fitted, the best kept: a fresh start of every contact
  // from the best set of atoms for the frame; the fitted discs plus the atom that best explains
  // what they leave; plus where the linear image of what they leave peaks. Then the caller's
  // remaining seeds, one at a time.
  // Then, where one more does not explain enough (one disc sits among several presses, and any
  // one more leaves the others), fresh starts of two and three more from the best atom sets.
  int stage = 0;
  std::vector<std::vector<Disc>> starts;
  const auto next_starts = [&] {
    starts.clear();
    const int k = static_cast<int>(discs.size());
    std::vector<Disc> set;
    if (stage == 0) {
      if (shared_.best_atom_set(dV / shared_.noise_V_, k + 1, set)) {
        for (Disc& d : set) d = shared_.clamp_seed(d);
        starts.push_back(std::move(set));
      }
      this->misfit(discs, dV, residual);
      std::vector<Disc> one;
      if (shared_.best_atom_set(-residual / shared_.noise_V_, 1, one)) add_starts(discs, one[0], starts);
      Disc seed;
      if (residual_peak && residual_peak(residual, seed)) add_starts(discs, seed, starts);
    } else if (stage <= 2) {
      // Only where the contacts leave more than a press's model error: several presses missed.
      if (k + stage + 1 <= shared_.options_.max_contacts && !shared_.explained(misfit_sq, dV) &&
          shared_.best_atom_set(dV / shared_.noise_V_, k + stage + 1, set)) {
        for (Disc& d : set) d = shared_.clamp_seed(d);
        starts.push_back(std::move(set));
      }
    } else if (next_seed < seeds.size()) {
      add_starts(discs, seeds[next_seed++], starts);
    }
    ++stage;
    return !starts.empty() || stage <= 3;
  };
  // One more contact is tried while the contacts do not explain the frame (explained(): beyond
  // the noise and a press's model error) or, once there are two or more, while the misfit is
  // beyond the noise (χ² above M by 4 of its σ, √(2M)): among three or four presses, two 12 mm
  // apart fitted by one disc between them leave less than a strong press's model error, which the
  // first rule alone misses (70 % of three presses found on the realistic twin; 95 % with both).
  // It is kept if it halves the misfit (a quarter for two more, an eighth for three) and the set
  // lies on the sheet, its discs apart; a contact the frame cannot place is dropped afterwards.
  int failed = 0;  // the caller's seeds cost a few fits each: give up after a few
  const double noise_sq = shared_.noise_V_ * shared_.noise_V_ * shared_.measurements_.size();
  const double beyond_noise_sq =
      shared_.noise_V_ * shared_.noise_V_ * 4 * std::sqrt(2.0 * shared_.measurements_.size());
  const auto another = [&] {
    return !shared_.explained(misfit_sq, dV) || (discs.size() >= 2 && misfit_sq > noise_sq + beyond_noise_sq);
  };
  while (static_cast<int>(discs.size()) < shared_.options_.max_contacts && another() && failed < 3 && next_starts()) {
    if (starts.empty()) continue;
    std::vector<Disc> more;
    double more_sq = 0;
    const bool any = fit_best_start(dV, starts, more, more_sq);
    const auto added = static_cast<int>(more.size()) - static_cast<int>(discs.size());
    if (any && more_sq <= std::pow(1 - new_contact_gain, added) * misfit_sq) {
      discs = std::move(more);
      misfit_sq = more_sq;
      stage = 0;
    } else if (stage > 3) {
      ++failed;
    }
  }
  finish(dV, discs, misfit_sq);
  // A contact the frame cannot place (its 1σ beyond the separation that tells two presses apart)
  // is not a press: a faint disc between others, taken in by a start of several at once. It is
  // left out and the rest refitted.
  for (bool dropped = true; dropped && discs.size() > 1;) {
    dropped = false;
    for (const FittedContact& c : result_.contacts)
      if (std::max(c.x_std_mm, c.y_std_mm) > shared_.plausible_separation_mm()) {
        const auto it = std::find_if(discs.begin(), discs.end(),
                                     [&](const Disc& d) { return d.x_mm == c.disc.x_mm && d.y_mm == c.disc.y_mm; });
        if (it == discs.end()) continue;
        discs.erase(it);
        const int evaluations = result_.evaluations;
        misfit_sq = fit_discs(dV, discs);
        result_ = {};
        result_.evaluations += evaluations;
        finish(dV, discs, misfit_sq);
        dropped = true;
        break;
      }
  }
  return result_;
}

}  // namespace emit
