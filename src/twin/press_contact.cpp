#include "emit/twin/press_contact.hpp"

#include <algorithm>
#include <array>
#include <cmath>

#include "emit/core/errors.hpp"
#include "emit/twin/press_pressure.hpp"

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

/// The four children of a piece, by its edges' midpoints.
std::array<Piece, 4> subdivide(const Piece& p) {
  auto mid = [&](int a, int b) {
    return std::pair<Vector2, Vector3>{0.5 * (p.corner[a] + p.corner[b]), 0.5 * (p.barycentric[a] + p.barycentric[b])};
  };
  const auto [m01, b01] = mid(0, 1);
  const auto [m12, b12] = mid(1, 2);
  const auto [m20, b20] = mid(2, 0);
  return {Piece{{p.corner[0], m01, m20}, {p.barycentric[0], b01, b20}},
          Piece{{m01, p.corner[1], m12}, {b01, p.barycentric[1], b12}},
          Piece{{m20, m12, p.corner[2]}, {b20, b12, p.barycentric[2]}}, Piece{{m01, m12, m20}, {b01, b12, b20}}};
}

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

  const std::vector<Disc>& discs_;
  const ContactLaw& law_;
};

/// The pressure of smooth presses (blurred by the cover, or spherical): a sum of radial profiles.
/// Triangles within a press's support are subdivided to pieces no longer than `target_mm` (small
/// against the blur or the profile), then up to `levels` more where the contact's edge (g's jump
/// at the minimum pressure, or an unblurred flat rim) crosses a piece; each piece is integrated
/// with the edge-midpoint rule, g taken at the three midpoints.
class SmoothIntegrator {
 public:
  SmoothIntegrator(const std::vector<Press>& presses, double blur_mm, const ContactLaw& law, int levels)
      : law_(law), levels_(levels) {
    for (const Press& p : presses) {
      profiles_.emplace_back(p, blur_mm);
      centres_.emplace_back(p.x_mm, p.y_mm);
      // Blurred: a quarter of the blur; unblurred (spherical, or a flat press beside one): an
      // eighth of the radius, the rim refined by `levels` as the flat path does.
      const double scale = blur_mm > 0 ? blur_mm / 4 : p.radius_mm / 8;
      target_mm_ = std::min(target_mm_, scale);
    }
  }

  const std::vector<RadialPressure>& profiles() const { return profiles_; }
  const std::vector<Vector2>& centres() const { return centres_; }

  void add(const Piece& piece, double area, int depth, int size_depth, Eigen::Matrix3d& local) const {
    bool reached = false, rim = false;
    for (std::size_t i = 0; i < profiles_.size(); ++i) {
      const Cover cover = classify(piece.corner, Disc{centres_[i], profiles_[i].support_mm(), 0});
      if (cover != Cover::none) reached = true;
      if (!profiles_[i].blurred() && cover == Cover::partial) rim = true;  // a jump in P or in P'
    }
    if (!reached) return;
    if (depth < size_depth) {
      for (const Piece& child : subdivide(piece)) add(child, area / 4, depth + 1, size_depth, local);
      return;
    }
    std::array<Vector3, 3> phi;
    std::array<double, 3> g{};
    int in_contact = 0;  // of the midpoints and the corners
    for (int k = 0; k < 3; ++k) {
      phi[k] = 0.5 * (piece.barycentric[k] + piece.barycentric[(k + 1) % 3]);
      g[k] = law_.conductance_S_per_mm2(pressure_at(0.5 * (piece.corner[k] + piece.corner[(k + 1) % 3])));
      in_contact += (g[k] > 0) + (law_.conductance_S_per_mm2(pressure_at(piece.corner[k])) > 0);
    }
    const bool edge = rim || (in_contact > 0 && in_contact < 6);
    if (edge && depth < size_depth + levels_) {
      for (const Piece& child : subdivide(piece)) add(child, area / 4, depth + 1, size_depth, local);
      return;
    }
    // Edge-midpoint rule: exact for the quadratic φ_i φ_j where g is constant on the piece.
    for (int k = 0; k < 3; ++k) local += (g[k] * area / 3.0) * phi[k] * phi[k].transpose();
  }

  /// Subdivisions (each halving the edges) that bring a triangle's longest edge to the target.
  int size_depth(const std::array<Vector2, 3>& corner) const {
    double longest = 0;
    for (int k = 0; k < 3; ++k) longest = std::max(longest, (corner[k] - corner[(k + 1) % 3]).norm());
    return longest > target_mm_ ? static_cast<int>(std::ceil(std::log2(longest / target_mm_))) : 0;
  }

 private:
  double pressure_at(const Vector2& p) const {
    double pressure = 0;
    for (std::size_t i = 0; i < profiles_.size(); ++i) pressure += profiles_[i].at((p - centres_[i]).norm());
    return pressure;
  }

  std::vector<RadialPressure> profiles_;
  std::vector<Vector2> centres_;
  const ContactLaw& law_;
  int levels_;
  double target_mm_ = 1e300;
};

}  // namespace

namespace {

/// The triangle t as a piece: its corners in the plane, barycentric coordinates the unit vectors.
Piece triangle_piece(const Mesh& mesh, Index t, Eigen::AlignedBox2d& box) {
  Piece piece;
  for (int k = 0; k < 3; ++k) {
    piece.corner[k] = mesh.nodes_mm.row(mesh.triangles(t, k)).head<2>().transpose();
    piece.barycentric[k] = Vector3::Unit(k);
    box.extend(piece.corner[k]);
  }
  return piece;
}

/// Blurred or spherical presses: SmoothIntegrator.
ContactLoad smooth_contact_load(const Mesh& mesh, const std::vector<Press>& pressing, const ContactLaw& law, int levels,
                                double blur_mm) {
  const SmoothIntegrator integrator(pressing, blur_mm, law, levels);
  Eigen::AlignedBox2d reach;
  for (std::size_t i = 0; i < pressing.size(); ++i) {
    const double s = integrator.profiles()[i].support_mm();
    reach.extend(integrator.centres()[i] - Vector2(s, s));
    reach.extend(integrator.centres()[i] + Vector2(s, s));
  }
  ContactLoad load;
  for (Index t = 0; t < mesh.triangle_count(); ++t) {
    Eigen::AlignedBox2d box;
    const Piece piece = triangle_piece(mesh, t, box);
    if (!box.intersects(reach)) continue;
    Eigen::Matrix3d local = Eigen::Matrix3d::Zero();
    integrator.add(piece, mesh.triangle_area_mm2(t), 0, integrator.size_depth(piece.corner), local);
    if (local.sum() > 0) {
      load.triangles.push_back(t);
      load.local_S.push_back(local);
    }
  }
  return load;
}

}  // namespace

ContactLoad press_contact_load(const Mesh& mesh, const std::vector<Press>& presses, const ContactLaw& law, int levels,
                               double blur_mm) {
  if (!(blur_mm >= 0) || !std::isfinite(blur_mm)) throw InvalidInput("cover blur must be finite and >= 0 mm");
  std::vector<Press> pressing;
  for (const auto& p : presses)
    if (p.force_N > 0) pressing.push_back(p);
  const bool smooth = blur_mm > 0 || std::any_of(pressing.begin(), pressing.end(),
                                                 [](const Press& p) { return p.profile != PressProfile::flat; });
  if (smooth && !pressing.empty()) return smooth_contact_load(mesh, pressing, law, levels, blur_mm);
  // Flat discs, unblurred: exact on triangles inside or outside, subdivided where a rim cuts.
  std::vector<Disc> discs;
  Eigen::AlignedBox2d reach;
  for (const auto& p : pressing) {
    discs.push_back({Vector2(p.x_mm, p.y_mm), p.radius_mm, p.pressure_N_per_mm2()});
    reach.extend(Vector2(p.x_mm - p.radius_mm, p.y_mm - p.radius_mm));
    reach.extend(Vector2(p.x_mm + p.radius_mm, p.y_mm + p.radius_mm));
  }
  ContactLoad load;
  if (discs.empty()) return load;
  const Integrator integrator(discs, law);
  for (Index t = 0; t < mesh.triangle_count(); ++t) {
    Eigen::AlignedBox2d box;
    const Piece piece = triangle_piece(mesh, t, box);
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
