#include "emit/eval/greit_merit.hpp"

#include <array>
#include <cmath>
#include <numbers>
#include <vector>

#include "emit/core/errors.hpp"

namespace emit {

namespace {

/// The barycentric centroids of a triangle's 4^levels similar pieces (corner midpoints): how
/// much of an element the circle C covers, by counting them (each holds 4^−levels of its area).
std::vector<Vector3> piece_centroids(int levels) {
  std::vector<std::array<Vector3, 3>> pieces{{Vector3(1, 0, 0), Vector3(0, 1, 0), Vector3(0, 0, 1)}};
  for (int level = 0; level < levels; ++level) {
    std::vector<std::array<Vector3, 3>> finer;
    for (const auto& [a, b, c] : pieces) {
      const Vector3 ab = (a + b) / 2, bc = (b + c) / 2, ca = (c + a) / 2;
      finer.push_back({a, ab, ca});
      finer.push_back({ab, b, bc});
      finer.push_back({ca, bc, c});
      finer.push_back({ab, bc, ca});
    }
    pieces = std::move(finer);
  }
  std::vector<Vector3> centroids;
  centroids.reserve(pieces.size());
  for (const auto& [a, b, c] : pieces) centroids.emplace_back((a + b + c) / 3);
  return centroids;
}

/// 4⁴ = 256 pieces: an element the circle's rim crosses is split to 1/16 of its size, so the
/// covered area's error is below 1 % of an element per rim crossing.
constexpr int circle_levels = 4;

}  // namespace

Vector2 sheet_centre_mm(const Mesh& mesh) {
  Vector2 sum(0, 0);
  double area = 0;
  for (Index t = 0; t < mesh.triangle_count(); ++t) {
    const double a = mesh.triangle_area_mm2(t);
    sum += a * mesh.triangle_centroid_mm(t).head<2>();
    area += a;
  }
  return sum / area;
}

GreitMerit greit_figures_of_merit(const Mesh& mesh, const Vector& image_in, const Vector2& target_centre_mm,
                                  double target_amount) {
  const Index n = mesh.triangle_count();
  if (image_in.size() != n)
    throw InvalidInput("figures of merit: the image has " + std::to_string(image_in.size()) + " values for " +
                       std::to_string(n) + " triangles");
  if (!image_in.allFinite()) throw InvalidInput("figures of merit: the image is not finite");
  if (!(target_amount > 0) || !std::isfinite(target_amount))
    throw InvalidInput("figures of merit: the target's amount must be positive");
  const double top = image_in.maxCoeff(), bottom = image_in.minCoeff();
  if (top == 0 && bottom == 0) throw InvalidInput("figures of merit: the image is 0 everywhere");
  const double sign = top >= -bottom ? 1.0 : -1.0;  // the target's direction: the larger magnitude
  const double threshold = 0.25 * sign * (sign > 0 ? top : bottom);

  GreitMerit m;
  double integral = 0, sheet_area = 0;
  Vector2 q_sum(0, 0);
  for (Index t = 0; t < n; ++t) {
    const double a = mesh.triangle_area_mm2(t), x = sign * image_in[t];
    integral += x * a;
    sheet_area += a;
    if (x >= threshold) {
      m.quarter_set_area_mm2 += a;
      q_sum += a * mesh.triangle_centroid_mm(t).head<2>();
    }
  }
  m.quarter_set_centre_mm = q_sum / m.quarter_set_area_mm2;
  m.amplitude_response = integral / target_amount;
  const Vector2 centre = sheet_centre_mm(mesh);
  m.position_error_mm = (target_centre_mm - centre).norm() - (m.quarter_set_centre_mm - centre).norm();
  m.resolution = std::sqrt(m.quarter_set_area_mm2 / sheet_area);

  // C: the circle of q's area about q's centre; each element's share of it by its pieces.
  const double radius_sq = m.quarter_set_area_mm2 / std::numbers::pi;
  const std::vector<Vector3> pieces = piece_centroids(circle_levels);
  double q_outside = 0, opposite_outside = 0, inside = 0;
  for (Index t = 0; t < n; ++t) {
    const double a = mesh.triangle_area_mm2(t), x = sign * image_in[t];
    Eigen::Matrix<double, 2, 3> corners;
    for (int k = 0; k < 3; ++k) corners.col(k) = mesh.nodes_mm.row(mesh.triangles(t, k)).head<2>().transpose();
    const Vector2 centroid = corners.rowwise().mean();
    const double reach = (corners.colwise() - centroid).colwise().norm().maxCoeff();
    const double distance = (centroid - m.quarter_set_centre_mm).norm(), radius = std::sqrt(radius_sq);
    double covered = distance + reach <= radius ? 1.0 : 0.0;
    if (distance - reach < radius && distance + reach > radius) {  // the rim crosses it
      for (const Vector3& b : pieces)
        if ((corners * b - m.quarter_set_centre_mm).squaredNorm() <= radius_sq) covered += 1;
      covered /= static_cast<double>(pieces.size());
    }
    if (x >= threshold) q_outside += (1 - covered) * a;
    if (x < 0) opposite_outside += -x * (1 - covered) * a;
    inside += x * covered * a;
  }
  m.shape_deformation = q_outside / m.quarter_set_area_mm2;
  m.ringing = inside > 0 ? opposite_outside / inside : INFINITY;
  return m;
}

}  // namespace emit
