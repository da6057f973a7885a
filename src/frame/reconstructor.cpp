#include "emit/frame/reconstructor.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

#include "emit/core/errors.hpp"
#include "emit/core/option_check.hpp"
#include "emit/model/image_noise.hpp"
#include "emit/sensor/surface.hpp"

namespace emit {

namespace {

/// The calibrated contact law's own error on a press of another size than the calibration
/// indenter's, as a σ of log F and log P beyond the frame's noise: the law absorbs the model's
/// error in a contact's total conductance G for the 5 mm discs it is calibrated on, and G errs
/// otherwise for a 2 or a 10 mm one. Measured with each disc's true radius declared, so that only
/// this is left (`emit eval --indenters --methods fit,shapes`, seed 21, 6 flat discs each of r 2,
/// 3, 5, 7, 10 mm): force ×0.93, 0.95, 0.98, 1.00, 1.02 (shapes; fit alike), RMS of ln F̂/F 0.042,
/// 0.045 with the presses' scatter.
constexpr double contact_law_log_std = 0.045;

}  // namespace

Reconstructor::Reconstructor(const ReconstructionModel& model, LinearCalibration calibration, FrameOptions options)
    : model_(model),
      linear_(calibration),
      options_(options),
      finder_(model.mesh, model.surface),
      reference_(Vector::Zero(model.measurements.size())),
      dV_(model.measurements.size()),
      dphi_(model.mesh.triangle_count()),
      pressure_(model.mesh.triangle_count()),
      fill_(model.measurements.size(), model.measurements.size() / 2),
      selected_(static_cast<std::size_t>(model.mesh.triangle_count())),
      operator_scratch_(model.op.scratch()) {
  options.validate();
  masked_.reserve(static_cast<std::size_t>(model.measurements.size()));
  if (linear_.force_law) {
    linear_.force_law->validate();
    image_forces_.emplace(model.mesh);
  }
  double sheet_area_mm2 = 0;
  for (Index t = 0; t < model.mesh.triangle_count(); ++t) sheet_area_mm2 += model.mesh.triangle_area_mm2(t);
  const double cell_mm2 = sheet_area_mm2 / std::max(1, model.measurements.size());
  min_area_mm2_ = std::max(options.min_contact_area_mm2, options.min_contact_cells * cell_mm2);
  const bool test = options.false_alarm_rate > 0 && model.reading_noise_V > 0 && model.op.rows() > 0;
  if (test) noise_per_volt_ = significance_sigmas(model.op.rows(), options.false_alarm_rate) * model.op.row_norms();
  floor_ = Vector::Constant(model.mesh.triangle_count(), -std::numeric_limits<double>::infinity());
  if (test) floor_ = difference_noise_V(model.reading_noise_V, 1) * noise_per_volt_;
}

Reconstructor::Reconstructor(const ReconstructionModel& model, const FitPrecompute& fit,
                             const FitCalibration& calibration, FrameOptions options)
    : Reconstructor(model, model.uncalibrated, options) {
  fitter_.emplace(fit);
  indenter_radius_mm_ = calibration.indenter_radius_mm;
  gamma_ = calibration.contact_law.gamma;
  law_ = fit.sensor().contact;
  if (options.contact_shapes) shapes_.emplace(fit);
}

void Reconstructor::set_reference(const Reference& reference) {
  const int N = model_.measurements.electrode_count;
  const Frame& frame = reference.frame;
  if (frame.rows() != N || frame.cols() != N)
    throw InvalidInput("reference frame has " + std::to_string(frame.size()) + " values, expected " +
                       std::to_string(N * N));
  if (!frame.array().isFinite().any()) throw InvalidInput("reference frame has no value that is a finite number");
  if (!(reference.frames >= 1))
    throw InvalidInput("reference: it stands for " + std::to_string(reference.frames) + " frames, at least 1 expected");
  for (int i = 0; i < model_.measurements.size(); ++i) reference_[i] = frame.data()[model_.measurements.frame_index[i]];
  previous_discs_.clear();  // a new reference starts a new stream
  if (noise_per_volt_.size() == floor_.size())
    floor_ = difference_noise_V(model_.reading_noise_V, reference.frames) * noise_per_volt_;
}

const std::vector<Contact>& Reconstructor::process(const FrameView& frame) {
  const int N = model_.measurements.electrode_count;
  if (frame.rows() != N || frame.cols() != N)
    throw InvalidInput("frame has " + std::to_string(frame.size()) + " values, expected " + std::to_string(N * N));
  masked_.clear();
  for (int i = 0; i < model_.measurements.size(); ++i) {
    const double v = frame.data()[model_.measurements.frame_index[i]];
    dV_[i] = v - reference_[i];
    if (!(std::isfinite(dV_[i]) && v < model_.clipped_at_V)) masked_.push_back(i), dV_[i] = 0;
  }
  if (!masked_.empty()) {
    // Beyond half the readings masked, or without the operator's precision, the frame tells
    // nothing: no change (a masked reading's 0 is its change's prior mean).
    if (static_cast<Index>(masked_.size()) > fill_.max_masked()) dV_.setZero();
    else if (model_.op.precision().size() > 0) fill_.fill(model_.op.precision(), masked_, dV_);
  }
  if (fitter_ && options_.track_contacts && !previous_discs_.empty()) {
    fitter_result_ = fitter_->track(dV_, previous_discs_);
    if (fitter_result_.tracked) {
      dphi_.setZero();
      return report_fitted();
    }
  }
  model_.op.apply(dV_, dphi_, operator_scratch_);  // paper eq. 7, precomputed
  const double peak = dphi_.maxCoeff();
  const double threshold = options_.threshold_fraction * peak;
  linear_.pressure_map(dphi_, threshold, pressure_, selected_);  // paper eq. 8 above the threshold
  const std::vector<Contact>& linear =
      finder_.find(selected_, pressure_, dphi_, min_area_mm2_, &floor_, threshold);  // significant ones, a cell or more
  if (fitter_) return fit_contacts(linear);
  return image_forces_ ? image_forces_->apply(*linear_.force_law, dphi_, linear) : linear;
}

const std::vector<Contact>& Reconstructor::fit_contacts(const std::vector<Contact>& linear) {
  // Seeds: the thresholded regions' centroids (the paper's estimate, strongest first), then the
  // image's other peaks above a quarter of its maximum (where the threshold merged two presses
  // into one region, the image still has two peaks). Raw peaks alone make poor first seeds: the
  // linear image's maximum often sits by an electrode, far from the press.
  seeds_.clear();
  for (const Contact& c : linear) {
    const Vector2 chart = chart_of(model_.surface, c);
    seeds_.push_back({chart.x(), chart.y(), 0, 0});
  }
  const std::size_t linear_seeds = seeds_.size();
  for (const Vector2& p : finder_.peaks(dphi_, 0.25 * dphi_.maxCoeff(), 8.0)) {
    bool apart = true;
    for (std::size_t i = 0; i < linear_seeds; ++i)
      apart = apart && std::hypot(p.x() - seeds_[i].x_mm, p.y() - seeds_[i].y_mm) >= 8.0;
    if (apart) seeds_.push_back({p.x(), p.y(), 0, 0});
  }
  // One more contact is proposed where the linear image of what the fit leaves unexplained peaks.
  const auto residual_peak = [this](const Vector& misfit, Disc& seed) {
    model_.op.apply(misfit, residual_image_, operator_scratch_);  // the image of −misfit is its negative
    Index peak;
    if (residual_image_.minCoeff(&peak) >= 0) return false;
    seed = {finder_.centroid_chart_mm(peak).x(), finder_.centroid_chart_mm(peak).y(), 0, 0};
    return true;
  };
  fitter_result_ = fitter_->fit(dV_, seeds_, residual_peak);
  return report_fitted();
}

/// The fit's contacts as the reconstruction reports them, and the picture: each disc at its pressure.
const std::vector<Contact>& Reconstructor::report_fitted() {
  fitted_.clear();
  previous_discs_.clear();
  pressure_.setZero();  // the picture: each fitted disc at its pressure
  if (shapes_) {
    for (const FittedContact& f : fitter_result_.contacts) previous_discs_.push_back(f.disc);
    // The area's prior: a declared indenter's, else the calibration indenter's (uncalibrated, a
    // fingertip's 5 mm) with the spread of the radii a user may press with.
    const AreaPrior prior =
        options_.contact_radius_mm > 0
            ? AreaPrior{options_.contact_radius_mm, options_.contact_radius_log_std}
            : AreaPrior{indenter_radius_mm_ > 0 ? indenter_radius_mm_ : 5.0, shapes_->options().log_radius_std};
    report_shapes(shapes_->refine(dV_, previous_discs_, prior));
    return fitted_;
  }
  const bool declared = options_.contact_radius_mm > 0;
  const double held_area_mm2 = std::numbers::pi * std::pow(fitter_->shared().options().prior_radius_mm, 2);
  const double indenter_area_mm2 =
      indenter_radius_mm_ > 0 ? std::numbers::pi * indenter_radius_mm_ * indenter_radius_mm_ : held_area_mm2;
  for (const FittedContact& f : fitter_result_.contacts) {
    Contact c;
    place_on_surface(model_.surface, {f.disc.x_mm, f.disc.y_mm}, c);
    const double radius_mm = declared                  ? options_.contact_radius_mm
                             : indenter_radius_mm_ > 0 ? indenter_radius_mm_
                                                       : f.disc.radius_mm;
    c.area_mm2 = std::numbers::pi * radius_mm * radius_mm;  // see FitCalibration::indenter_radius_mm
    // A declared area: the calibrated law at the held disc's conductance scaled to it, as
    // report_shapes says.
    c.pressure_N_per_mm2 = c.peak_pressure_N_per_mm2 =
        declared ? law_.pressure_N_per_mm2(f.disc.conductance_S_per_mm2 * std::pow(f.disc.radius_mm, 2) /
                                           std::pow(fitter_->shared().options().prior_radius_mm, 2) *
                                           indenter_area_mm2 / c.area_mm2)
                 : f.pressure_N_per_mm2;
    c.force_N = c.pressure_N_per_mm2 * c.area_mm2;
    c.x_std_mm = f.x_std_mm, c.y_std_mm = f.y_std_mm;
    ellipse_outline({f.disc.x_mm, f.disc.y_mm}, radius_mm, radius_mm, 0, c.outline);  // the reported area's circle
    // F = P·A with A the calibration indenter's: the frame pins G = A^(1+γ) F^(−γ)/α (paper eq.
    // 2), so log F = const + log G/(−γ) + (1 + γ)/γ · log A. The fit's σ of log G; an indenter of
    // unknown size, log A's σ as shape_refiner.hpp's prior (radii 2–10 mm about the
    // calibration's), or a declared one's; and the law's own error across sizes.
    const double log_area_std = 2 * (declared ? options_.contact_radius_log_std : ShapeOptions{}.log_radius_std);
    const double fit_part = f.pressure_N_per_mm2 > 0 ? f.pressure_std_N_per_mm2 / f.pressure_N_per_mm2 : 0;
    const double area_part = (1 + gamma_) / gamma_ * log_area_std;
    c.force_std_N = c.force_N * std::hypot(std::hypot(fit_part, area_part), contact_law_log_std);
    c.pressure_std_N_per_mm2 = c.pressure_N_per_mm2 * std::hypot(fit_part, contact_law_log_std);
    fitted_.push_back(c);
    previous_discs_.push_back(f.disc);
    for (Index k = 0; k < pressure_.size(); ++k)
      if ((finder_.centroid_mm(k) - Vector3(c.x_mm, c.y_mm, c.z_mm)).norm() <= radius_mm)
        pressure_[k] = std::max(pressure_[k], c.pressure_N_per_mm2);
  }
  return fitted_;
}

/// The refitted ellipses as contacts (shape_refiner.hpp). The contact law as calibrated maps the
/// held disc's conductance g_h = G/(π r_h²) to the pressure of a press of the calibration
/// indenter's area A_c; a press of area A and pressure P has G = A g(P), so its pressure is the
/// calibrated law's at g_h·A_c/A (uncalibrated, the nominal law's at G/A: A_c = π r_h²).
void Reconstructor::report_shapes(const std::vector<RefinedContact>& shapes) {
  const double held_area_mm2 = std::numbers::pi * std::pow(fitter_->shared().options().prior_radius_mm, 2);
  const double indenter_area_mm2 =
      indenter_radius_mm_ > 0 ? std::numbers::pi * indenter_radius_mm_ * indenter_radius_mm_ : held_area_mm2;
  for (const RefinedContact& r : shapes) {
    const Ellipse& e = r.ellipse;
    Contact c;
    place_on_surface(model_.surface, {e.x_mm, e.y_mm}, c);
    c.area_mm2 = e.area_mm2();
    const double total_S = e.conductance_S_per_mm2 * c.area_mm2;
    c.pressure_N_per_mm2 = c.peak_pressure_N_per_mm2 =
        law_.pressure_N_per_mm2(total_S / held_area_mm2 * indenter_area_mm2 / c.area_mm2);
    c.force_N = c.pressure_N_per_mm2 * c.area_mm2;
    c.x_std_mm = r.x_std_mm, c.y_std_mm = r.y_std_mm;
    // P = (α g)^(−1/γ): log P = −(log G − log A)/γ + const, log F = log P + log A.
    const double k = -1 / law_.gamma;
    const double var_G = r.log_conductance_std * r.log_conductance_std, var_A = r.log_area_std * r.log_area_std;
    const double cov = r.log_conductance_log_area_cov;
    const double law_var = contact_law_log_std * contact_law_log_std;
    const double log_P_var = k * k * (var_G + var_A - 2 * cov) + law_var;
    const double log_F_var = k * k * var_G + (1 - k) * (1 - k) * var_A + 2 * k * (1 - k) * cov + law_var;
    c.pressure_std_N_per_mm2 = c.pressure_N_per_mm2 * std::sqrt(std::max(0.0, log_P_var));
    c.force_std_N = c.force_N * std::sqrt(std::max(0.0, log_F_var));
    c.area_std_mm2 = c.area_mm2 * r.log_area_std;
    c.semi_major_mm = e.semi_major_mm(), c.semi_minor_mm = e.semi_minor_mm();
    c.orientation_deg = e.orientation_rad() * 180 / std::numbers::pi;
    c.orientation_std_deg = r.orientation_std_rad * 180 / std::numbers::pi;
    ellipse_outline({e.x_mm, e.y_mm}, c.semi_major_mm, c.semi_minor_mm, c.orientation_deg, c.outline);
    if (is_curved(model_.surface))  // the ellipse lies in the tangent plane: its vertices as chart points
      for (int k = 0; k < c.outline.size; ++k) {
        const Vector2 centre(e.x_mm, e.y_mm);
        const Vector2 v = shapes_->integrator().chart_point(centre, c.outline.vertex_mm(k) - centre);
        c.outline.vertices_mm[static_cast<std::size_t>(k)] = {static_cast<float>(v.x()), static_cast<float>(v.y())};
      }
    fitted_.push_back(c);
    for (Index t = 0; t < pressure_.size(); ++t) {
      const Vector2& p = finder_.centroid_chart_mm(t);
      if (shapes_->integrator().contains(e, p)) pressure_[t] = std::max(pressure_[t], c.pressure_N_per_mm2);
    }
  }
  std::sort(fitted_.begin(), fitted_.end(), [](const Contact& a, const Contact& b) { return a.force_N > b.force_N; });
}

void FrameOptions::validate() const {
  if (!(threshold_fraction > 0 && threshold_fraction < 1))
    option_check::fail("FrameOptions", "threshold_fraction", "a fraction in (0, 1)",
                       std::to_string(threshold_fraction));
  option_check::non_negative("FrameOptions", "min_contact_area_mm2", min_contact_area_mm2);
  option_check::non_negative("FrameOptions", "min_contact_cells", min_contact_cells);
  option_check::non_negative("FrameOptions", "contact_radius_mm", contact_radius_mm);
  option_check::positive("FrameOptions", "contact_radius_log_std", contact_radius_log_std);
  if (!(false_alarm_rate >= 0 && false_alarm_rate < 1))
    option_check::fail("FrameOptions", "false_alarm_rate", "in [0, 1)", std::to_string(false_alarm_rate));
}
}  // namespace emit
