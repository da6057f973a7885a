#include "emit/eval/resolvability.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>
#include <string>

#include "emit/core/errors.hpp"
#include "emit/frame/contact_fitter.hpp"
#include "emit/model/image_noise.hpp"

namespace emit {

namespace {

constexpr int piece_levels = 3;  ///< 64 pieces a triangle: 1/8 of an element across

/// Splits a triangle (corner barycentrics B, rows) into 4^levels similar pieces.
void split(const Eigen::Matrix3d& B, int levels, std::vector<Eigen::Matrix3d>& out) {
  if (levels == 0) {
    out.push_back(B);
    return;
  }
  const Eigen::RowVector3d m01 = (B.row(0) + B.row(1)) / 2, m12 = (B.row(1) + B.row(2)) / 2,
                           m20 = (B.row(2) + B.row(0)) / 2;
  Eigen::Matrix3d child;
  child << B.row(0), m01, m20;
  split(child, levels - 1, out);
  child << m01, B.row(1), m12;
  split(child, levels - 1, out);
  child << m20, m12, B.row(2);
  split(child, levels - 1, out);
  child << m01, m12, m20;
  split(child, levels - 1, out);
}

/// C¹ step: 0 for ξ ≤ −1, 1 for ξ ≥ 1 (as the fitter's disc rim, frame/disc_contact.hpp).
double smoothstep(double xi) {
  if (xi >= 1) return 1;
  if (xi <= -1) return 0;
  const double t = (xi + 1) / 2;
  return t * t * (3 - 2 * t);
}

double rectangle_distance(const Vector2& p, const Vector2& centre, double half_x, double half_y) {
  const Vector2 q = (p - centre).cwiseAbs() - Vector2(half_x, half_y);
  return q.cwiseMax(0.0).norm() + std::min(std::max(q.x(), q.y()), 0.0);
}

}  // namespace

void require_flat_sheet(const Sensor& sensor, const std::string& what) {
  const ShapeKind k = sensor.shape.kind;
  if (k != ShapeKind::rectangle && k != ShapeKind::circle && k != ShapeKind::polygon)
    throw InvalidInput(what + ": a flat sheet only (a rectangle, circle or polygon)");
}

Resolvability::Resolvability(const Sensor& sensor, const FitModel& fit, const MeasurementSet& measurements,
                             int reference_frames)
    : sensor_(sensor),
      fit_(fit),
      measurements_(measurements),
      predictor_(fit.mesh, fit.green),
      integrator_(fit.mesh, resolved_fit_options({}, sensor, fit.mesh).edge_mm, 3, sensor.shape) {
  require_flat_sheet(sensor, "resolvability");
  if (reference_frames < 1) throw InvalidInput("resolvability: the reference must average one frame or more");
  noise_V_ = difference_noise_V(reading_noise_V(sensor.adc), reference_frames);
  predictor_.set_series_resistance(sensor.series_resistance_ohm);
  std::vector<Eigen::Matrix3d> corners;
  split(Eigen::Matrix3d::Identity(), piece_levels, corners);
  Eigen::Matrix3d mu = Eigen::Matrix3d::Constant(1.0 / 12);
  mu.diagonal().setConstant(2.0 / 12);
  const double fraction = std::pow(0.25, piece_levels);
  for (const Eigen::Matrix3d& B : corners) {
    piece_barycentric_.emplace_back(B.colwise().mean().transpose());
    piece_integrals_.emplace_back(fraction * B.transpose() * mu * B);  // ∫ μ_k μ_l = a (1 + δ_kl) / 12
  }
}

Eigen::Matrix<double, Eigen::Dynamic, 4> Resolvability::round_contact_jacobian(const Vector2& centre_mm,
                                                                               double radius_mm, double force_N,
                                                                               Vector* dV) {
  if (!(radius_mm > 0) || !(force_N > 0)) throw InvalidInput("resolvability: radius and force must be positive");
  const double pressure = force_N / (std::numbers::pi * radius_mm * radius_mm);
  const Disc disc{centre_mm.x(), centre_mm.y(), radius_mm, sensor_.contact.conductance_S_per_mm2(pressure)};
  DiscLoad load;
  integrator_.integrate(disc, load, true);
  predictor_.predict(load.triangles, load.local_S, sensor_.drive_voltage_V, frame_);
  const int M = measurements_.size();
  if (dV) {
    dV->resize(M);
    for (int i = 0; i < M; ++i) (*dV)[i] = frame_.data()[measurements_.frame_index[i]];
  }
  Eigen::Matrix<double, Eigen::Dynamic, 4> J(M, 4);
  std::vector<Eigen::Matrix3d> d_local(load.triangles.size());
  for (int k = 0; k < 4; ++k) {
    for (std::size_t t = 0; t < load.triangles.size(); ++t)
      d_local[t] = k < 3 ? load.d_local_S[t][static_cast<std::size_t>(k)] : load.local_S[t];  // ∂C/∂log g = C
    predictor_.derivative(load.triangles, d_local, d_frame_);
    for (int i = 0; i < M; ++i) J(i, k) = d_frame_.data()[measurements_.frame_index[i]] / noise_V_;
  }
  return J;
}

RoundContactBound Resolvability::round_contact_bound(const Vector2& centre_mm, double radius_mm, double force_N) {
  Vector dV;
  const Eigen::Matrix<double, Eigen::Dynamic, 4> J = round_contact_jacobian(centre_mm, radius_mm, force_N, &dV);
  RoundContactBound bound;
  bound.signal_rms_V = std::sqrt(dV.squaredNorm() / static_cast<double>(dV.size()));
  const Eigen::Matrix4d covariance = (J.transpose() * J).inverse();  // F⁻¹, F = JᵀJ/σ²
  const auto std_along = [&](const Eigen::Vector4d& gradient) {
    return std::sqrt(gradient.dot(covariance * gradient));
  };
  bound.x_std_mm = std::sqrt(covariance(0, 0));
  bound.y_std_mm = std::sqrt(covariance(1, 1));
  bound.radius_std_mm = std::sqrt(covariance(2, 2));
  bound.log_conductance_std = std::sqrt(covariance(3, 3));
  bound.log_total_std = std_along(Eigen::Vector4d(0, 0, 2 / radius_mm, 1));  // log(g·πr²)
  // F = P·πr², r_c = 1/g = α P^γ (eq. 2): log P = −(log α + log g)/γ.
  bound.log_force_std = std_along(Eigen::Vector4d(0, 0, 2 / radius_mm, -1 / sensor_.contact.gamma));
  return bound;
}

Vector Resolvability::region_dV(const SignedDistance& region, double conductance_S_per_mm2) {
  const Mesh& mesh = fit_.mesh;
  std::vector<Index> triangles;
  std::vector<Eigen::Matrix3d> local;
  for (Index t = 0; t < mesh.triangle_count(); ++t) {
    Eigen::Matrix3d corner;
    for (int k = 0; k < 3; ++k) corner.row(k) = mesh.nodes_mm.row(mesh.triangles(t, k));
    const Vector2 centroid = corner.colwise().mean().head<2>().transpose();
    double reach = 0;
    for (int k = 0; k < 3; ++k) reach = std::max(reach, (corner.row(k).head<2>().transpose() - centroid).norm());
    const double d = region(centroid);  // 1-Lipschitz: no point of the triangle is nearer the inside
    if (d - reach >= rim_mm) continue;
    Eigen::Matrix3d integral = Eigen::Matrix3d::Zero();
    if (d + reach <= -rim_mm) {
      for (const Eigen::Matrix3d& piece : piece_integrals_) integral += piece;
    } else {
      for (std::size_t i = 0; i < piece_integrals_.size(); ++i) {
        const Vector2 p = (corner.transpose() * piece_barycentric_[i]).head<2>();
        integral += smoothstep(-region(p) / rim_mm) * piece_integrals_[i];
      }
    }
    if (integral.isZero()) continue;
    triangles.push_back(t);
    local.emplace_back(conductance_S_per_mm2 * mesh.triangle_area_mm2(t) * integral);
  }
  predictor_.predict(triangles, local, sensor_.drive_voltage_V, frame_);  // no contact: a frame of 0
  Vector dV(measurements_.size());
  for (int i = 0; i < measurements_.size(); ++i) dV[i] = frame_.data()[measurements_.frame_index[i]];
  return dV;
}

AlternativeFit Resolvability::fit_alternative(const Vector& target,
                                              const std::function<SignedDistance(const Eigen::VectorXd&)>& shape,
                                              Eigen::VectorXd parameters, const Eigen::VectorXd& steps,
                                              bool hold_last) {
  const Index n = parameters.size();  // the last is log g
  const auto residual = [&](const Eigen::VectorXd& q) -> Vector {
    return (region_dV(shape(q), std::exp(q[n - 1])) - target) / noise_V_;
  };
  Vector r = residual(parameters);
  double cost = r.squaredNorm(), lambda = 1e-3;
  Matrix J(r.size(), n);
  bool converged = false;
  for (int iteration = 0; iteration < 50 && !converged && cost > 0; ++iteration) {
    for (Index k = 0; k < n; ++k) {  // central differences: Δχ² is ~1e-7 of the signal's χ²
      if (hold_last && k == n - 1) {
        J.col(k).setZero();  // no step along it (the damping keeps the system regular)
        continue;
      }
      Eigen::VectorXd up = parameters, down = parameters;
      up[k] += steps[k], down[k] -= steps[k];
      J.col(k) = (residual(up) - residual(down)) / (2 * steps[k]);
    }
    const Matrix JtJ = J.transpose() * J;
    const Eigen::VectorXd gradient = J.transpose() * r;
    bool improved = false;
    for (int attempt = 0; attempt < 12 && !improved; ++attempt) {
      Matrix A = JtJ;
      A.diagonal() += lambda * JtJ.diagonal().cwiseMax(1e-12);
      const Eigen::VectorXd step = -A.ldlt().solve(gradient);
      Eigen::VectorXd q = parameters + step;
      for (Index k = 0; k + 1 < n; ++k) q[k] = std::max(q[k], 0.2);  // lengths stay positive
      const Vector r_new = residual(q);
      if (r_new.squaredNorm() < cost) {
        const double gain = cost - r_new.squaredNorm();
        parameters = q, r = r_new, cost = r_new.squaredNorm();
        lambda = std::max(lambda / 3, 1e-7);
        improved = true;
        converged = gain < 1e-4 * std::max(cost, 1e-2);
      } else {
        lambda *= 10;
      }
    }
    if (!improved) break;
  }
  AlternativeFit fit;
  fit.delta_chi2 = cost;
  fit.parameters.assign(parameters.data(), parameters.data() + n);
  fit.signal_chi2 = (target / noise_V_).squaredNorm();
  return fit;
}

AlternativeFit Resolvability::two_bars_against_one(const Vector2& centre_mm, double width_mm, double length_mm,
                                                   double gap_mm, double pressure_N_per_mm2, bool hold_pressure) {
  if (!(width_mm > 0) || !(length_mm > 0) || gap_mm < 0 || !(pressure_N_per_mm2 > 0))
    throw InvalidInput("resolvability: bars need a positive width, length and pressure and a gap ≥ 0");
  const double g = sensor_.contact.conductance_S_per_mm2(pressure_N_per_mm2);
  const double offset = (width_mm + gap_mm) / 2;
  const SignedDistance two = [=](const Vector2& p) {
    if (gap_mm == 0) return rectangle_distance(p, centre_mm, width_mm, length_mm / 2);  // one bar, no seam
    return std::min(rectangle_distance(p, centre_mm - Vector2(offset, 0), width_mm / 2, length_mm / 2),
                    rectangle_distance(p, centre_mm + Vector2(offset, 0), width_mm / 2, length_mm / 2));
  };
  const Vector target = region_dV(two, g);
  const auto one = [=](const Eigen::VectorXd& q) -> SignedDistance {
    return [=](const Vector2& p) { return rectangle_distance(p, centre_mm, q[0] / 2, q[1] / 2); };
  };
  const double outer = 2 * width_mm + gap_mm;
  Eigen::VectorXd start(3), steps(3);
  // The same total conductance, or (held) the same pressure and so about the bars' area.
  start << (hold_pressure ? 2 * width_mm : outer), length_mm, std::log(hold_pressure ? g : g * 2 * width_mm / outer);
  steps << 0.05, 0.05, 0.005;
  return fit_alternative(target, one, start, steps, hold_pressure);
}

AlternativeFit Resolvability::ring_against_disc(const Vector2& centre_mm, double inner_mm, double outer_mm,
                                                double pressure_N_per_mm2, bool hold_pressure) {
  if (!(inner_mm >= 0) || !(outer_mm > inner_mm) || !(pressure_N_per_mm2 > 0))
    throw InvalidInput("resolvability: a ring needs 0 ≤ inner < outer radius and a positive pressure");
  const double g = sensor_.contact.conductance_S_per_mm2(pressure_N_per_mm2);
  const SignedDistance ring = [=](const Vector2& p) {
    const double d = (p - centre_mm).norm();
    return inner_mm > 0 ? std::max(d - outer_mm, inner_mm - d) : d - outer_mm;  // no hole: a disc
  };
  const Vector target = region_dV(ring, g);
  const auto disc = [=](const Eigen::VectorXd& q) -> SignedDistance {
    return [=](const Vector2& p) { return (p - centre_mm).norm() - q[0]; };
  };
  Eigen::VectorXd start(2), steps(2);
  const double area_fraction = 1 - inner_mm * inner_mm / (outer_mm * outer_mm);
  start << (hold_pressure ? outer_mm * std::sqrt(area_fraction) : outer_mm),
      std::log(hold_pressure ? g : g * area_fraction);
  steps << 0.05, 0.005;
  return fit_alternative(target, disc, start, steps, hold_pressure);
}

}  // namespace emit
