#include "emit/eval/outline_scoring.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <numbers>

#include "emit/core/errors.hpp"
#include "emit/sensor/press_outline.hpp"

namespace emit {

namespace {

/// The centroids of a triangle's 4^levels pieces (its edges cut into 2^levels), as (s, t): the
/// point v0 + s (v1 − v0) + t (v2 − v0).
std::vector<Vector2> piece_centroids(int levels) {
  const int n = 1 << levels;
  std::vector<Vector2> points;
  for (int i = 0; i < n; ++i)
    for (int j = 0; i + j < n; ++j) {
      points.emplace_back((i + 1.0 / 3) / n, (j + 1.0 / 3) / n);                     // pointing up
      if (i + j < n - 1) points.emplace_back((i + 2.0 / 3) / n, (j + 2.0 / 3) / n);  // and down
    }
  return points;
}

/// Where a press's edge may cut a triangle: its polygons' edges' boxes, or its disc.
struct PressReach {
  const Press* press;
  Eigen::AlignedBox2d box;
  std::vector<Eigen::AlignedBox2d> edge_boxes;  ///< empty for a disc
};

bool covered(const std::vector<Press>& presses, const Vector2& p) {
  return std::any_of(presses.begin(), presses.end(), [&](const Press& press) { return press_covers(press, p); });
}

/// Whether the edge of `r` may cross the triangle whose corners are `t` and box `box`.
bool may_cut(const PressReach& r, const std::array<Vector2, 3>& t, const Eigen::AlignedBox2d& box) {
  if (!box.intersects(r.box)) return false;
  if (r.edge_boxes.empty()) {  // a disc: cut unless wholly inside (it is convex) or wholly outside
    const Vector2 centre(r.press->x_mm, r.press->y_mm);
    int inside = 0;
    for (const Vector2& v : t) inside += (v - centre).norm() <= r.press->radius_mm;
    if (inside == 3) return false;
    return inside > 0 || box.exteriorDistance(centre) < r.press->radius_mm;
  }
  return std::any_of(r.edge_boxes.begin(), r.edge_boxes.end(),
                     [&](const Eigen::AlignedBox2d& e) { return box.intersects(e); });
}

}  // namespace

Vector outline_coverage(const Mesh& mesh, const std::vector<Press>& presses, int levels) {
  Vector fraction = Vector::Zero(mesh.triangle_count());
  if (presses.empty()) return fraction;
  std::vector<PressReach> reach;
  Eigen::AlignedBox2d all;
  for (const Press& p : presses) {
    PressReach r{&p, {}, {}};
    const Vector2 centre(p.x_mm, p.y_mm);
    if (p.outline_mm.empty()) {
      r.box.extend(centre - Vector2::Constant(p.radius_mm)).extend(centre + Vector2::Constant(p.radius_mm));
    } else {
      for (const auto& polygon : placed_outline_mm(p))
        for (std::size_t i = 0; i < polygon.size(); ++i) {
          const Vector2 &a = polygon[i], &b = polygon[(i + 1) % polygon.size()];
          r.edge_boxes.emplace_back(a.cwiseMin(b), a.cwiseMax(b));
          r.box.extend(a);
        }
    }
    all.extend(r.box);
    reach.push_back(std::move(r));
  }
  const std::vector<Vector2> pieces = piece_centroids(levels);
  for (Index k = 0; k < mesh.triangle_count(); ++k) {
    std::array<Vector2, 3> t;
    Eigen::AlignedBox2d box;
    for (int c = 0; c < 3; ++c) {
      t[static_cast<std::size_t>(c)] = mesh.nodes_mm.row(mesh.triangles(k, c)).head<2>().transpose();
      box.extend(t[static_cast<std::size_t>(c)]);
    }
    if (!box.intersects(all)) continue;
    const bool cut = std::any_of(reach.begin(), reach.end(), [&](const PressReach& r) { return may_cut(r, t, box); });
    if (!cut) {
      fraction[k] = covered(presses, (t[0] + t[1] + t[2]) / 3) ? 1.0 : 0.0;
      continue;
    }
    int inside = 0;
    for (const Vector2& st : pieces) inside += covered(presses, t[0] + st.x() * (t[1] - t[0]) + st.y() * (t[2] - t[0]));
    fraction[k] = static_cast<double>(inside) / static_cast<double>(pieces.size());
  }
  return fraction;
}

double area_dice(const Vector& areas_mm2, const Vector& reconstructed, const Vector& truth) {
  const double a = areas_mm2.dot(reconstructed), b = areas_mm2.dot(truth);
  if (a + b == 0) return 1.0;
  return 2 * areas_mm2.dot(reconstructed.cwiseProduct(truth)) / (a + b);
}

double principal_angle_deg(const Eigen::Matrix2d& second_moments) {
  const Eigen::Matrix2d& m = second_moments;
  const double angle = 0.5 * std::atan2(2 * m(0, 1), m(0, 0) - m(1, 1)) * 180 / std::numbers::pi;
  return angle <= -90 ? angle + 180 : angle;
}

double axis_difference_deg(double a_deg, double b_deg) {
  const double d = std::fmod(std::abs(a_deg - b_deg), 180.0);
  return std::min(d, 180 - d);
}

OutlineTruth outline_truth(const std::vector<Press>& presses) {
  OutlineTruth truth;
  Eigen::Matrix2d raw = Eigen::Matrix2d::Zero();  // ∫ p pᵀ dA
  for (const Press& p : presses) {
    const double area = press_area_mm2(p);
    const Vector2 c = press_centroid_mm(p);
    truth.area_mm2 += area;
    truth.force_N += p.force_N;
    truth.centroid_mm += area * c;
    raw += area * (press_second_moments_mm2(p) + c * c.transpose());
  }
  if (!(truth.area_mm2 > 0)) return truth;
  truth.centroid_mm /= truth.area_mm2;
  truth.second_moments_mm2 = raw / truth.area_mm2 - truth.centroid_mm * truth.centroid_mm.transpose();
  const Eigen::Matrix2d& m = truth.second_moments_mm2;  // a symmetric 2×2's eigenvalues
  const double mean = (m(0, 0) + m(1, 1)) / 2, spread = std::hypot((m(0, 0) - m(1, 1)) / 2, m(0, 1));
  truth.elongated = mean + spread >= elongated_ratio * (mean - spread);
  truth.angle_deg = principal_angle_deg(truth.second_moments_mm2);
  return truth;
}

bool within_sigmas(double value, double std, double truth, double k) {
  if (!(value > 0 && truth > 0)) return false;
  return std::abs(std::log(value / truth)) <= k * std / value;
}

OutlineScore score_outline_frame(const Mesh& mesh, const Vector& coverage, const Vector& pressure,
                                 const std::vector<Contact>& contacts, const std::vector<Press>& presses) {
  if (pressure.size() != mesh.triangle_count() || coverage.size() != mesh.triangle_count())
    throw InvalidInput("outline scoring: " + std::to_string(pressure.size()) + " pressures and " +
                       std::to_string(coverage.size()) + " coverages for " + std::to_string(mesh.triangle_count()) +
                       " triangles");
  Vector areas(mesh.triangle_count()), region(mesh.triangle_count());
  double area = 0;
  Vector2 first = Vector2::Zero();
  Eigen::Matrix2d second = Eigen::Matrix2d::Zero();
  for (Index k = 0; k < mesh.triangle_count(); ++k) {
    areas[k] = mesh.triangle_area_mm2(k);
    region[k] = pressure[k] > 0 ? 1.0 : 0.0;
    if (region[k] == 0) continue;
    const Vector2 c = mesh.triangle_centroid_mm(k).head<2>();
    area += areas[k];
    first += areas[k] * c;
    second += areas[k] * c * c.transpose();  // the pieces' own moments (h²/…) are small against a region's
  }
  OutlineScore score;
  score.dice = area_dice(areas, region, coverage);
  double area_var = 0, force_var = 0;
  for (const Contact& c : contacts) {
    score.force_N += c.force_N;
    score.area_mm2 += c.area_mm2;
    area_var += c.area_std_mm2 * c.area_std_mm2;
    force_var += c.force_std_N * c.force_std_N;
  }
  score.area_std_mm2 = std::sqrt(area_var);
  score.force_std_N = std::sqrt(force_var);
  const OutlineTruth truth = outline_truth(presses);
  score.true_area_mm2 = truth.area_mm2;
  score.true_force_N = truth.force_N;
  score.region_area_mm2 = area;
  score.regions = static_cast<int>(contacts.size());
  score.presses = static_cast<int>(presses.size());
  constexpr double none = std::numeric_limits<double>::quiet_NaN();
  score.centroid_error_mm = none;
  score.orientation_error_deg = truth.elongated ? 90.0 : none;
  if (area > 0) {
    const Vector2 centroid = first / area;
    score.centroid_error_mm = (centroid - truth.centroid_mm).norm();
    if (truth.elongated) {
      const Eigen::Matrix2d moments = second / area - centroid * centroid.transpose();
      score.orientation_error_deg = axis_difference_deg(principal_angle_deg(moments), truth.angle_deg);
    }
  }
  return score;
}

}  // namespace emit
