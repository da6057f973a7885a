#include "emit/twin/press_contact.hpp"

#include <algorithm>
#include <array>

namespace emit {

namespace {

struct Disc {
  Vector2 center;
  double radius;
  double pressure;
};

enum class Cover { none, full, partial };

double segment_distance(const Vector2& p, const Vector2& a, const Vector2& b) {
  const Vector2 d = b - a;
  const double t = std::clamp((p - a).dot(d) / d.squaredNorm(), 0.0, 1.0);
  return (a + t * d - p).norm();
}

bool inside_triangle(const Vector2& p, const std::array<Vector2, 3>& t) {
  auto side = [&](int i) {
    const Vector2& a = t[i];
    const Vector2& b = t[(i + 1) % 3];
    return (b.x() - a.x()) * (p.y() - a.y()) - (b.y() - a.y()) * (p.x() - a.x());
  };
  const double s0 = side(0), s1 = side(1), s2 = side(2);
  return (s0 >= 0 && s1 >= 0 && s2 >= 0) || (s0 <= 0 && s1 <= 0 && s2 <= 0);
}

Cover classify(const std::array<Vector2, 3>& t, const Disc& d) {
  int inside = 0;
  for (const auto& v : t) inside += (v - d.center).norm() <= d.radius;
  if (inside == 3) return Cover::full;  // a disc is convex
  if (inside > 0 || inside_triangle(d.center, t)) return Cover::partial;
  double distance = segment_distance(d.center, t[0], t[1]);
  distance = std::min(distance, segment_distance(d.center, t[1], t[2]));
  distance = std::min(distance, segment_distance(d.center, t[2], t[0]));
  return distance < d.radius ? Cover::partial : Cover::none;
}

/// A sub-triangle: its corners in the plane and their barycentric coordinates in the parent.
struct Piece {
  std::array<Vector2, 3> corner;
  std::array<Vector3, 3> barycentric;
};

class Integrator {
 public:
  Integrator(const std::vector<Disc>& discs, const ContactLaw& law) : discs_(discs), law_(law) {}

  /// Adds ∫_piece g φ_i φ_j over a piece of area `area` to `local`.
  void add(const Piece& piece, double area, int levels_left, Eigen::Matrix3d& local) const {
    double pressure = 0;
    bool cut = false;
    for (const auto& d : discs_) {
      const Cover cover = classify(piece.corner, d);
      if (cover == Cover::full) pressure += d.pressure;
      if (cover == Cover::partial) cut = true;
    }
    if (cut && levels_left > 0) {
      for (const Piece& child : subdivide(piece)) add(child, area / 4, levels_left - 1, local);
      return;
    }
    if (cut) pressure = pressure_at((piece.corner[0] + piece.corner[1] + piece.corner[2]) / 3);
    const double g = law_.conductance_S_per_mm2(pressure);
    if (g == 0) return;
    // Edge-midpoint rule: exact for the quadratic φ_i φ_j on the piece.
    for (int k = 0; k < 3; ++k) {
      const Vector3 phi = 0.5 * (piece.barycentric[k] + piece.barycentric[(k + 1) % 3]);
      local += (g * area / 3.0) * phi * phi.transpose();
    }
  }

 private:
  double pressure_at(const Vector2& p) const {
    double pressure = 0;
    for (const auto& d : discs_)
      if ((p - d.center).norm() <= d.radius) pressure += d.pressure;
    return pressure;
  }

  static std::array<Piece, 4> subdivide(const Piece& p) {
    auto mid = [&](int a, int b) {
      return std::pair<Vector2, Vector3>{0.5 * (p.corner[a] + p.corner[b]),
                                         0.5 * (p.barycentric[a] + p.barycentric[b])};
    };
    const auto [m01, b01] = mid(0, 1);
    const auto [m12, b12] = mid(1, 2);
    const auto [m20, b20] = mid(2, 0);
    return {Piece{{p.corner[0], m01, m20}, {p.barycentric[0], b01, b20}},
            Piece{{m01, p.corner[1], m12}, {b01, p.barycentric[1], b12}},
            Piece{{m20, m12, p.corner[2]}, {b20, b12, p.barycentric[2]}}, Piece{{m01, m12, m20}, {b01, b12, b20}}};
  }

  const std::vector<Disc>& discs_;
  const ContactLaw& law_;
};

}  // namespace

ContactLoad press_contact_load(const Mesh& mesh, const std::vector<Press>& presses, const ContactLaw& law, int levels) {
  std::vector<Disc> discs;
  Eigen::AlignedBox2d reach;
  for (const auto& p : presses) {
    if (p.force_N <= 0) continue;
    discs.push_back({Vector2(p.x_mm, p.y_mm), p.radius_mm, p.pressure_N_per_mm2()});
    reach.extend(Vector2(p.x_mm - p.radius_mm, p.y_mm - p.radius_mm));
    reach.extend(Vector2(p.x_mm + p.radius_mm, p.y_mm + p.radius_mm));
  }
  ContactLoad load;
  if (discs.empty()) return load;
  const Integrator integrator(discs, law);
  for (Index t = 0; t < mesh.triangle_count(); ++t) {
    Piece piece;
    Eigen::AlignedBox2d box;
    for (int k = 0; k < 3; ++k) {
      piece.corner[k] = mesh.nodes_mm.row(mesh.triangles(t, k)).head<2>().transpose();
      piece.barycentric[k] = Vector3::Unit(k);
      box.extend(piece.corner[k]);
    }
    if (!box.intersects(reach)) continue;
    Eigen::Matrix3d local = Eigen::Matrix3d::Zero();
    integrator.add(piece, mesh.triangle_area_mm2(t), levels, local);
    if (local.sum() > 0) {
      load.triangles.push_back(t);
      load.local_S.push_back(local);
    }
  }
  return load;
}

}  // namespace emit
