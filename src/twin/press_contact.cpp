#include "emit/twin/press_contact.hpp"

#include <algorithm>
#include <array>
#include <cmath>

#include "emit/core/errors.hpp"
#include "emit/mesh/flatness.hpp"
#include "emit/sensor/press_outline.hpp"
#include "emit/twin/press_pressure.hpp"

namespace emit {

namespace {

/// A press's contact: the points of the sheet within `radius` (3D distance) of `center`, a point
/// on the sheet. On a flat sheet a disc; on a curved one the sheet inside a ball, as the
/// conformance frames of a spherical cap define it (their README).
struct Disc {
  Vector3 center;
  double radius;
  double pressure;
};

enum class Cover { none, full, partial };

/// The distance from p to the triangle t in 3D (the closest point's, Ericson's regions).
double triangle_distance(const Vector3& p, const std::array<Vector3, 3>& t) {
  const Vector3 ab = t[1] - t[0], ac = t[2] - t[0], ap = p - t[0];
  const double d1 = ab.dot(ap), d2 = ac.dot(ap);
  if (d1 <= 0 && d2 <= 0) return ap.norm();
  const Vector3 bp = p - t[1];
  const double d3 = ab.dot(bp), d4 = ac.dot(bp);
  if (d3 >= 0 && d4 <= d3) return bp.norm();
  const double vc = d1 * d4 - d3 * d2;
  if (vc <= 0 && d1 >= 0 && d3 <= 0) return (p - (t[0] + d1 / (d1 - d3) * ab)).norm();
  const Vector3 cp = p - t[2];
  const double d5 = ab.dot(cp), d6 = ac.dot(cp);
  if (d6 >= 0 && d5 <= d6) return cp.norm();
  const double vb = d5 * d2 - d1 * d6;
  if (vb <= 0 && d2 >= 0 && d6 <= 0) return (p - (t[0] + d2 / (d2 - d6) * ac)).norm();
  const double va = d3 * d6 - d5 * d4;
  if (va <= 0 && (d4 - d3) >= 0 && (d5 - d6) >= 0)
    return (p - (t[1] + (d4 - d3) / ((d4 - d3) + (d5 - d6)) * (t[2] - t[1]))).norm();
  const double denominator = 1 / (va + vb + vc);
  return (p - (t[0] + ab * (vb * denominator) + ac * (vc * denominator))).norm();
}

Cover classify(const std::array<Vector3, 3>& t, const Disc& d) {
  int inside = 0;
  for (const auto& v : t) inside += (v - d.center).norm() <= d.radius;
  if (inside == 3) return Cover::full;  // a ball is convex
  if (inside > 0) return Cover::partial;
  return triangle_distance(d.center, t) < d.radius ? Cover::partial : Cover::none;
}

/// A sub-triangle: its corners and their barycentric coordinates in the parent.
struct Piece {
  std::array<Vector3, 3> corner;
  std::array<Vector3, 3> barycentric;
};

/// The four children of a piece, by its edges' midpoints.
std::array<Piece, 4> subdivide(const Piece& p) {
  auto mid = [&](int a, int b) {
    return std::pair<Vector3, Vector3>{0.5 * (p.corner[a] + p.corner[b]), 0.5 * (p.barycentric[a] + p.barycentric[b])};
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
  double pressure_at(const Vector3& p) const {
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
      centres_.emplace_back(p.x_mm, p.y_mm, p.z_mm);
      // Blurred: a quarter of the blur; unblurred (spherical, or a flat press beside one): an
      // eighth of the radius, the rim refined by `levels` as the flat path does.
      const double scale = blur_mm > 0 ? blur_mm / 4 : p.radius_mm / 8;
      target_mm_ = std::min(target_mm_, scale);
    }
  }

  const std::vector<RadialPressure>& profiles() const { return profiles_; }
  const std::vector<Vector3>& centres() const { return centres_; }

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
  int size_depth(const std::array<Vector3, 3>& corner) const {
    double longest = 0;
    for (int k = 0; k < 3; ++k) longest = std::max(longest, (corner[k] - corner[(k + 1) % 3]).norm());
    return longest > target_mm_ ? static_cast<int>(std::ceil(std::log2(longest / target_mm_))) : 0;
  }

 private:
  double pressure_at(const Vector3& p) const {
    double pressure = 0;
    for (std::size_t i = 0; i < profiles_.size(); ++i) pressure += profiles_[i].at((p - centres_[i]).norm());
    return pressure;
  }

  std::vector<RadialPressure> profiles_;
  std::vector<Vector3> centres_;
  const ContactLaw& law_;
  int levels_;
  double target_mm_ = 1e300;
};

/// A flat press's contact on a flat sheet, a disc or an outline (sensor/press_outline.hpp), seen
/// in the sheet's x, y: its polygons' edges (none for a disc), their bounding box, its pressure.
struct FlatRegion {
  const Press* press;
  std::vector<std::vector<Vector2>> polygons;  ///< placed (absolute); empty for a disc
  std::vector<std::array<Vector2, 2>> edges;
  Eigen::AlignedBox2d box;
  double pressure;
};

double orient(const Vector2& a, const Vector2& b, const Vector2& c) {
  return (b - a).x() * (c - a).y() - (b - a).y() * (c - a).x();
}

/// Whether the closed segments pq and ab meet (touching counts).
bool segments_meet(const Vector2& p, const Vector2& q, const Vector2& a, const Vector2& b) {
  const double d1 = orient(a, b, p), d2 = orient(a, b, q), d3 = orient(p, q, a), d4 = orient(p, q, b);
  if (((d1 > 0 && d2 < 0) || (d1 < 0 && d2 > 0)) && ((d3 > 0 && d4 < 0) || (d3 < 0 && d4 > 0))) return true;
  const auto on = [](const Vector2& u, const Vector2& v, const Vector2& w, double d) {
    return d == 0 && std::min(u.x(), v.x()) <= w.x() && w.x() <= std::max(u.x(), v.x()) &&
           std::min(u.y(), v.y()) <= w.y() && w.y() <= std::max(u.y(), v.y());
  };
  return on(a, b, p, d1) || on(a, b, q, d2) || on(p, q, a, d3) || on(p, q, b, d4);
}

bool in_triangle(const std::array<Vector2, 3>& t, const Vector2& p) {
  const double d0 = orient(t[0], t[1], p), d1 = orient(t[1], t[2], p), d2 = orient(t[2], t[0], p);
  return !((d0 < 0 || d1 < 0 || d2 < 0) && (d0 > 0 || d1 > 0 || d2 > 0));
}

/// Whether a piece (2D) is wholly inside a region, wholly outside, or cut by its edge: cut when
/// one of the outline's edges meets the piece, else inside or outside as its centroid is.
Cover classify_outline(const std::array<Vector2, 3>& t, const FlatRegion& r) {
  Eigen::AlignedBox2d box(t[0]);
  box.extend(t[1]).extend(t[2]);
  if (!box.intersects(r.box)) return Cover::none;
  for (const auto& [a, b] : r.edges) {
    if (!box.intersects(Eigen::AlignedBox2d(a.cwiseMin(b), a.cwiseMax(b)))) continue;
    if (in_triangle(t, a) || in_triangle(t, b)) return Cover::partial;
    for (int k = 0; k < 3; ++k)
      if (segments_meet(t[k], t[(k + 1) % 3], a, b)) return Cover::partial;
  }
  return inside_polygons(r.polygons, (t[0] + t[1] + t[2]) / 3) ? Cover::full : Cover::none;
}

/// Flat presses of which some have an outline, on a flat sheet: Integrator's rule (exact on pieces
/// wholly inside or outside every region, subdivided `levels` times where an edge cuts, the
/// pressure at the last pieces' centroids), with discs classified as Integrator does.
class OutlineIntegrator {
 public:
  OutlineIntegrator(const std::vector<FlatRegion>& regions, const ContactLaw& law) : regions_(regions), law_(law) {}

  void add(const Piece& piece, double area, int levels_left, Eigen::Matrix3d& local) const {
    const std::array<Vector2, 3> flat{piece.corner[0].head<2>(), piece.corner[1].head<2>(), piece.corner[2].head<2>()};
    double pressure = 0;
    bool cut = false;
    for (const FlatRegion& r : regions_) {
      const Cover cover = r.polygons.empty()
                              ? classify(piece.corner, Disc{Vector3(r.press->x_mm, r.press->y_mm, r.press->z_mm),
                                                            r.press->radius_mm, r.pressure})
                              : classify_outline(flat, r);
      if (cover == Cover::full) pressure += r.pressure;
      if (cover == Cover::partial) cut = true;
    }
    if (cut && levels_left > 0) {
      for (const Piece& child : subdivide(piece)) add(child, area / 4, levels_left - 1, local);
      return;
    }
    if (cut) {
      pressure = 0;
      const Vector3 centroid = (piece.corner[0] + piece.corner[1] + piece.corner[2]) / 3;
      for (const FlatRegion& r : regions_)
        if (press_covers(*r.press, centroid.head<2>())) pressure += r.pressure;
    }
    const double g = law_.conductance_S_per_mm2(pressure);
    if (g == 0) return;
    for (int k = 0; k < 3; ++k) {
      const Vector3 phi = 0.5 * (piece.barycentric[k] + piece.barycentric[(k + 1) % 3]);
      local += (g * area / 3.0) * phi * phi.transpose();
    }
  }

 private:
  const std::vector<FlatRegion>& regions_;
  const ContactLaw& law_;
};

}  // namespace

namespace {

/// The triangle t as a piece: its corners, barycentric coordinates the unit vectors.
Piece triangle_piece(const Mesh& mesh, Index t, Eigen::AlignedBox3d& box) {
  Piece piece;
  for (int k = 0; k < 3; ++k) {
    piece.corner[k] = mesh.nodes_mm.row(mesh.triangles(t, k)).transpose();
    piece.barycentric[k] = Vector3::Unit(k);
    box.extend(piece.corner[k]);
  }
  return piece;
}

/// Blurred or spherical presses: SmoothIntegrator.
ContactLoad smooth_contact_load(const Mesh& mesh, const std::vector<Press>& pressing, const ContactLaw& law, int levels,
                                double blur_mm) {
  const SmoothIntegrator integrator(pressing, blur_mm, law, levels);
  Eigen::AlignedBox3d reach;
  for (std::size_t i = 0; i < pressing.size(); ++i) {
    const double s = integrator.profiles()[i].support_mm();
    reach.extend(integrator.centres()[i] - Vector3::Constant(s));
    reach.extend(integrator.centres()[i] + Vector3::Constant(s));
  }
  ContactLoad load;
  for (Index t = 0; t < mesh.triangle_count(); ++t) {
    Eigen::AlignedBox3d box;
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

/// Flat presses of which some have an outline, on a flat sheet: OutlineIntegrator.
ContactLoad outline_contact_load(const Mesh& mesh, const std::vector<Press>& pressing, const ContactLaw& law,
                                 int levels) {
  std::vector<FlatRegion> regions;
  Eigen::AlignedBox3d reach;
  for (const Press& p : pressing) {
    FlatRegion r{&p, placed_outline_mm(p), {}, {}, p.pressure_N_per_mm2()};
    const Vector2 centre(p.x_mm, p.y_mm);
    r.box.extend(centre);
    if (r.polygons.empty()) {
      r.box.extend(centre - Vector2::Constant(p.radius_mm)).extend(centre + Vector2::Constant(p.radius_mm));
    }
    for (const auto& polygon : r.polygons)
      for (std::size_t i = 0; i < polygon.size(); ++i) {
        r.edges.push_back({polygon[i], polygon[(i + 1) % polygon.size()]});
        r.box.extend(polygon[i]);
      }
    reach.extend(Vector3(r.box.min().x(), r.box.min().y(), 0)).extend(Vector3(r.box.max().x(), r.box.max().y(), 0));
    regions.push_back(std::move(r));
  }
  const OutlineIntegrator integrator(regions, law);
  ContactLoad load;
  for (Index t = 0; t < mesh.triangle_count(); ++t) {
    Eigen::AlignedBox3d box;
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

}  // namespace

ContactLoad press_contact_load(const Mesh& mesh, const std::vector<Press>& presses, const ContactLaw& law, int levels,
                               double blur_mm) {
  if (!(blur_mm >= 0) || !std::isfinite(blur_mm)) throw InvalidInput("cover blur must be finite and >= 0 mm");
  std::vector<Press> pressing;
  for (const auto& p : presses)
    if (p.force_N > 0) pressing.push_back(p);
  const bool outlined =
      std::any_of(pressing.begin(), pressing.end(), [](const Press& p) { return !p.outline_mm.empty(); });
  if (outlined) {
    if (blur_mm > 0) throw InvalidInput("an outline press under a blurring cover is not simulated (cover blur 0 only)");
    for (const Press& p : pressing)
      if (p.profile != PressProfile::flat) throw InvalidInput("outline presses go with flat presses only");
    if (!is_flat(mesh)) throw InvalidInput("an outline press needs a flat sheet");
    for (const Press& p : pressing)
      if (!p.outline_mm.empty()) validate_outline(p.outline_mm, "outline press");
    return outline_contact_load(mesh, pressing, law, levels);
  }
  const bool smooth = blur_mm > 0 || std::any_of(pressing.begin(), pressing.end(),
                                                 [](const Press& p) { return p.profile != PressProfile::flat; });
  if (smooth && !pressing.empty()) return smooth_contact_load(mesh, pressing, law, levels, blur_mm);
  // Flat discs, unblurred: exact on triangles inside or outside, subdivided where a rim cuts.
  std::vector<Disc> discs;
  Eigen::AlignedBox3d reach;
  for (const auto& p : pressing) {
    const Vector3 center(p.x_mm, p.y_mm, p.z_mm);
    discs.push_back({center, p.radius_mm, p.pressure_N_per_mm2()});
    reach.extend(center - Vector3::Constant(p.radius_mm));
    reach.extend(center + Vector3::Constant(p.radius_mm));
  }
  ContactLoad load;
  if (discs.empty()) return load;
  const Integrator integrator(discs, law);
  for (Index t = 0; t < mesh.triangle_count(); ++t) {
    Eigen::AlignedBox3d box;
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
