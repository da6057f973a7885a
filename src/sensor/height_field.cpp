#include "emit/sensor/height_field.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <numbers>

#include "emit/core/errors.hpp"

namespace emit {

namespace {

/// A triangle's normal times twice its area, on the +z side.
Vector3 upward_normal(const HeightField::Nodes& nodes, const HeightField::Triangles& triangles, Index t) {
  const Vector3 a = nodes.row(triangles(t, 0)), b = nodes.row(triangles(t, 1)), c = nodes.row(triangles(t, 2));
  const Vector3 n = (b - a).cross(c - a);
  return n.z() < 0 ? Vector3(-n) : n;
}

}  // namespace

std::optional<std::vector<int>> border_loop(const HeightField::Triangles& triangles) {
  std::map<std::pair<int, int>, int> uses;
  for (Index t = 0; t < triangles.rows(); ++t)
    for (int k = 0; k < 3; ++k) {
      const int a = triangles(t, k), b = triangles(t, (k + 1) % 3);
      ++uses[{std::min(a, b), std::max(a, b)}];
    }
  std::map<int, std::vector<int>> next;
  std::size_t edges = 0;
  for (const auto& [edge, count] : uses)
    if (count == 1) {
      next[edge.first].push_back(edge.second), next[edge.second].push_back(edge.first);
      ++edges;
    }
  if (edges < 3) return std::nullopt;
  for (const auto& [node, neighbours] : next)
    if (neighbours.size() != 2) return std::nullopt;
  std::vector<int> loop{next.begin()->first};
  int previous = -1;
  while (loop.size() <= edges) {
    const std::vector<int>& n = next[loop.back()];
    const int following = n[0] != previous ? n[0] : n[1];
    previous = loop.back();
    if (following == loop.front()) break;
    loop.push_back(following);
  }
  if (loop.size() != edges) return std::nullopt;
  return loop;
}

HeightField::HeightField(Nodes nodes_mm, Triangles triangles, const std::string& context)
    : nodes_mm_(std::move(nodes_mm)), triangles_(std::move(triangles)) {
  if (triangles_.rows() == 0) throw InvalidInput(context + ": the surface has no triangles");
  double edge_sum_mm = 0;
  for (Index t = 0; t < triangles_.rows(); ++t) {
    const Vector3 n = upward_normal(nodes_mm_, triangles_, t);
    area_mm2_ += n.norm() / 2;
    // cos 89°: steeper, and the chart (x, y) would stretch a millimetre of it over 57 of the sheet.
    if (!(n.z() > std::cos(89.0 * std::numbers::pi / 180) * n.norm())) {
      const Vector3 centre = centroid_mm(t);
      char text[200];
      std::snprintf(text, sizeof text, "a triangle at (%.3g, %.3g, %.3g) mm is seen edge-on from +z", centre.x(),
                    centre.y(), centre.z());
      throw InvalidInput(context + ": " + text +
                         "; emit charts a surface from a file by (x, y), so it must face +z everywhere (turn it so)");
    }
    for (int k = 0; k < 3; ++k)
      edge_sum_mm += (nodes_mm_.row(triangles_(t, k)) - nodes_mm_.row(triangles_(t, (k + 1) % 3))).norm();
  }
  curved_ = nodes_mm_.col(2).cwiseAbs().maxCoeff() > 0;
  box_ = {nodes_mm_.leftCols<2>().colwise().minCoeff().transpose(),
          nodes_mm_.leftCols<2>().colwise().maxCoeff().transpose()};
  // Cells about an edge long: a few triangles each.
  cell_mm_ = std::max(edge_sum_mm / (3.0 * static_cast<double>(triangles_.rows())), 1e-9);
  const Vector2 sizes = box_.sizes() / cell_mm_;
  cells_ = {std::max(1, static_cast<int>(std::ceil(sizes.x()))), std::max(1, static_cast<int>(std::ceil(sizes.y())))};
  const auto cell_count = static_cast<std::size_t>(cells_.x()) * static_cast<std::size_t>(cells_.y());
  if (cell_count > 64 * static_cast<std::size_t>(triangles_.rows()) + 1024)
    throw InvalidInput(context + ": the surface is too thin seen from +z to chart");
  std::vector<std::vector<int>> lists(cell_count);
  for (Index t = 0; t < triangles_.rows(); ++t) {
    Eigen::AlignedBox2d b;
    for (int k = 0; k < 3; ++k) b.extend(Vector2(nodes_mm_.row(triangles_(t, k)).head<2>().transpose()));
    const Eigen::Vector2i lo = cell_of(b.min()), hi = cell_of(b.max());
    for (int j = lo.y(); j <= hi.y(); ++j)
      for (int i = lo.x(); i <= hi.x(); ++i)
        lists[static_cast<std::size_t>(j) * static_cast<std::size_t>(cells_.x()) + static_cast<std::size_t>(i)]
            .push_back(static_cast<int>(t));
  }
  cell_start_.assign(1, 0);
  for (const auto& list : lists) {
    cell_triangles_.insert(cell_triangles_.end(), list.begin(), list.end());
    cell_start_.push_back(static_cast<int>(cell_triangles_.size()));
  }
  // Seen once from +z: no triangle's centroid lies inside another triangle.
  for (Index t = 0; t < triangles_.rows(); ++t) {
    const Vector3 centre = centroid_mm(t);
    const Vector2 centroid = centre.head<2>();
    const Eigen::Vector2i cell = cell_of(centroid);
    const std::size_t index =
        static_cast<std::size_t>(cell.y()) * static_cast<std::size_t>(cells_.x()) + static_cast<std::size_t>(cell.x());
    for (int k = cell_start_[index]; k < cell_start_[index + 1]; ++k) {
      const Index other = cell_triangles_[static_cast<std::size_t>(k)];
      if (other != t && barycentric(other, centroid).minCoeff() > 1e-9) {
        char text[200];
        std::snprintf(text, sizeof text, "the surface covers (%.3g, %.3g) mm twice seen from +z (near z = %.3g mm)",
                      centroid.x(), centroid.y(), centre.z());
        throw InvalidInput(context + ": " + text +
                           "; emit charts a surface from a file by (x, y), so it must not fold over itself");
      }
    }
  }
  if (const auto loop = border_loop(triangles_)) {
    std::vector<Vector2> points;
    for (int v : *loop) points.emplace_back(nodes_mm_(v, 0), nodes_mm_(v, 1));
    try {
      outline_ = Border::polygon(points);
    } catch (const InvalidInput&) {
      // A border that crosses itself seen from +z has no outline: press scripts say so.
    }
  }
}

Vector3 HeightField::centroid_mm(Index t) const {
  return (nodes_mm_.row(triangles_(t, 0)) + nodes_mm_.row(triangles_(t, 1)) + nodes_mm_.row(triangles_(t, 2)))
             .transpose() /
         3;
}

Eigen::Vector2i HeightField::cell_of(const Vector2& c) const {
  const Vector2 q = (c - box_.min()) / cell_mm_;
  return {std::clamp(static_cast<int>(std::floor(q.x())), 0, cells_.x() - 1),
          std::clamp(static_cast<int>(std::floor(q.y())), 0, cells_.y() - 1)};
}

Vector3 HeightField::barycentric(Index t, const Vector2& c) const {
  const Vector2 a = nodes_mm_.row(triangles_(t, 0)).head<2>(), b = nodes_mm_.row(triangles_(t, 1)).head<2>(),
                d = nodes_mm_.row(triangles_(t, 2)).head<2>();
  const double det = (b.x() - a.x()) * (d.y() - a.y()) - (d.x() - a.x()) * (b.y() - a.y());
  const double l1 = ((c.x() - a.x()) * (d.y() - a.y()) - (d.x() - a.x()) * (c.y() - a.y())) / det;
  const double l2 = ((b.x() - a.x()) * (c.y() - a.y()) - (c.x() - a.x()) * (b.y() - a.y())) / det;
  return {1 - l1 - l2, l1, l2};
}

Vector2 HeightField::nearest_on_triangle(Index t, const Vector2& c) const {
  Vector2 best = c;
  double best_sq = std::numeric_limits<double>::infinity();
  for (int k = 0; k < 3; ++k) {
    const Vector2 a = nodes_mm_.row(triangles_(t, k)).head<2>(),
                  b = nodes_mm_.row(triangles_(t, (k + 1) % 3)).head<2>();
    const double along = std::clamp((c - a).dot(b - a) / (b - a).squaredNorm(), 0.0, 1.0);
    const Vector2 q = a + along * (b - a);
    if ((q - c).squaredNorm() < best_sq) best_sq = (q - c).squaredNorm(), best = q;
  }
  return best;
}

Index HeightField::locate(const Vector2& c, Vector3& weights) const {
  const Eigen::Vector2i cell = cell_of(c);
  Index best = -1;
  double best_mm = std::numeric_limits<double>::infinity();
  // Rings of cells about c's until a triangle holds c, or, beyond the border, one ring past the
  // first that has a triangle (the nearest is then among those seen).
  for (int ring = 0; ring <= std::max(cells_.x(), cells_.y()); ++ring) {
    for (int j = cell.y() - ring; j <= cell.y() + ring; ++j)
      for (int i = cell.x() - ring; i <= cell.x() + ring; ++i) {
        if (std::max(std::abs(i - cell.x()), std::abs(j - cell.y())) != ring) continue;
        if (i < 0 || j < 0 || i >= cells_.x() || j >= cells_.y()) continue;
        const std::size_t index =
            static_cast<std::size_t>(j) * static_cast<std::size_t>(cells_.x()) + static_cast<std::size_t>(i);
        for (int k = cell_start_[index]; k < cell_start_[index + 1]; ++k) {
          const Index t = cell_triangles_[static_cast<std::size_t>(k)];
          const Vector3 w = barycentric(t, c);
          if (w.minCoeff() >= 0) {
            weights = w;
            return t;
          }
          const Vector2 q = nearest_on_triangle(t, c);
          if ((q - c).norm() < best_mm) best_mm = (q - c).norm(), best = t, weights = barycentric(t, q);
        }
      }
    if (best >= 0 && ring > 0) break;
  }
  return best;
}

Vector3 HeightField::point_mm(const Vector2& c) const {
  Vector3 w;
  const Index t = locate(c, w);
  double z_mm = 0;
  for (int k = 0; k < 3; ++k) z_mm += w[k] * nodes_mm_(triangles_(t, k), 2);
  return {c.x(), c.y(), z_mm};
}

Vector3 HeightField::normal(const Vector2& c) const {
  Vector3 w;
  return upward_normal(nodes_mm_, triangles_, locate(c, w)).normalized();
}

Eigen::Matrix<double, 3, 2> HeightField::tangents(const Vector2& c) const {
  const Vector3 n = normal(c);
  Eigen::Matrix<double, 3, 2> t;
  t << 1, 0, 0, 1, -n.x() / n.z(), -n.y() / n.z();
  return t;
}

}  // namespace emit
