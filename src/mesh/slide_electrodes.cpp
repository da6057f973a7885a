#include "emit/mesh/slide_electrodes.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "emit/core/errors.hpp"
#include "emit/core/option_check.hpp"

namespace emit {

namespace {

/// Signed arc length from a to b the short way round, in (−L/2, L/2].
double arc_between(double a_mm, double b_mm, double length_mm) {
  double d = std::fmod(b_mm - a_mm, length_mm);
  if (d > 0.5 * length_mm) d -= length_mm;
  if (d <= -0.5 * length_mm) d += length_mm;
  return d;
}

/// Arc lengths where the border turns (a polygon's or rectangle's corners; none on a circle).
std::vector<double> corners(const Border& border) {
  std::vector<double> out;
  const double eps = 1e-6 * border.length_mm();
  for (const BorderPiece& piece : border.pieces()) {
    const double s = piece.start_s_mm;
    const Vector2 before = (border.point_at(s) - border.point_at(s - eps)).normalized();
    const Vector2 after = (border.point_at(s + eps) - border.point_at(s)).normalized();
    if (before.dot(after) < 1 - 1e-9) out.push_back(s);
  }
  return out;
}

/// The displacement's weight at a distance x beyond the rigid zone's edge (1 inside, 0 beyond).
double falloff(double x_mm, double rigid_mm, double reach_mm) {
  if (x_mm <= rigid_mm) return 1;
  if (x_mm >= rigid_mm + reach_mm) return 0;
  return 1 - (x_mm - rigid_mm) / reach_mm;
}

struct Zone {
  double rigid_mm = 0, reach_mm = 0;
};

/// Each electrode's zone: the options', shrunk to 45 % of the gap to its neighbours and 90 % of
/// the way to the nearest corner; none for an electrode over a corner.
std::vector<Zone> zones(const Sensor& sensor, const SlideOptions& options) {
  const Border& border = *sensor.border;
  const double L = border.length_mm();
  const std::vector<double> turns = corners(border);
  const auto& electrodes = sensor.electrodes;
  std::vector<Zone> out;
  for (std::size_t e = 0; e < electrodes.size(); ++e) {
    const double half = 0.5 * electrodes[e].width_mm;
    double room = options.rigid_mm + options.reach_mm;
    for (std::size_t o = 0; o < electrodes.size(); ++o) {
      if (o == e) continue;
      const double gap = std::abs(arc_between(electrodes[e].center_s_mm, electrodes[o].center_s_mm, L)) - half -
                         0.5 * electrodes[o].width_mm;
      room = std::min(room, 0.45 * gap);
    }
    for (double s : turns) {
      const double away = std::abs(arc_between(electrodes[e].center_s_mm, s, L)) - half;
      room = std::min(room, away <= 0 ? 0.0 : 0.9 * away);
    }
    const double scale = std::max(0.0, room) / (options.rigid_mm + options.reach_mm);
    out.push_back({scale * options.rigid_mm, scale * options.reach_mm});
  }
  return out;
}

void check_shifts(const Sensor& sensor, const std::vector<double>& shift_mm) {
  if (!sensor.border) throw InvalidInput("sliding electrodes needs an analytic border, not a mesh-file sheet");
  if (shift_mm.size() != sensor.electrodes.size())
    throw InvalidInput("electrode shifts: " + std::to_string(shift_mm.size()) + " for " +
                       std::to_string(sensor.electrodes.size()) + " electrodes");
  for (double s : shift_mm)
    if (!std::isfinite(s)) throw InvalidInput("electrode shifts: must be finite");
}

}  // namespace

Mesh slide_electrodes(const Mesh& mesh, const Sensor& sensor, const std::vector<double>& shift_mm,
                      const SlideOptions& options) {
  options.validate();
  check_shifts(sensor, shift_mm);
  if (mesh.electrode_count() != static_cast<int>(sensor.electrodes.size()))
    throw InvalidInput("sliding electrodes: the mesh has " + std::to_string(mesh.electrode_count()) +
                       " electrodes, the sensor " + std::to_string(sensor.electrodes.size()));
  const Border& border = *sensor.border;
  const double L = border.length_mm();
  const std::vector<Zone> zone = zones(sensor, options);
  for (std::size_t e = 0; e < zone.size(); ++e)
    if (shift_mm[e] != 0 && !(std::abs(shift_mm[e]) <= 0.5 * zone[e].reach_mm))
      throw InvalidInput("electrode " + std::to_string(e) + ": a shift of " + std::to_string(shift_mm[e]) +
                         " mm is more than its room to slide (" + std::to_string(0.5 * zone[e].reach_mm) + " mm)");
  Mesh out = mesh;
  const double on_border_mm = 1e-7 * border.size_mm();
  const double eps = 1e-4;  // mm, for the tangent
  for (Index v = 0; v < mesh.node_count(); ++v) {
    const Vector2 p = mesh.nodes_mm.row(v).head<2>().transpose();
    const Border::Projection at = border.project(p);
    double along = 0;  // the node's displacement along the border [mm]
    for (std::size_t e = 0; e < zone.size(); ++e) {
      if (shift_mm[e] == 0 || zone[e].reach_mm == 0) continue;
      const double from_electrode = std::max(0.0, std::abs(arc_between(sensor.electrodes[e].center_s_mm, at.s_mm, L)) -
                                                      0.5 * sensor.electrodes[e].width_mm);
      along += shift_mm[e] * falloff(from_electrode, zone[e].rigid_mm, zone[e].reach_mm) *
               falloff(at.distance_mm, zone[e].rigid_mm, zone[e].reach_mm);
    }
    if (along == 0) continue;
    Vector2 moved;
    if (at.distance_mm <= on_border_mm) {
      moved = border.point_at(at.s_mm + along);
    } else {
      const Vector2 tangent = (border.point_at(at.s_mm + eps) - border.point_at(at.s_mm - eps)).normalized();
      moved = p + along * tangent;
    }
    out.nodes_mm(v, 0) = moved.x();
    out.nodes_mm(v, 1) = moved.y();
  }
  // A slide within the room keeps every triangle's orientation; say so if it did not.
  for (Index t = 0; t < out.triangle_count(); ++t) {
    const auto orientation = [&](const Mesh& m) {
      const Vector2 a = m.nodes_mm.row(m.triangles(t, 0)).head<2>().transpose();
      const Vector2 b = m.nodes_mm.row(m.triangles(t, 1)).head<2>().transpose();
      const Vector2 c = m.nodes_mm.row(m.triangles(t, 2)).head<2>().transpose();
      return (b - a).x() * (c - a).y() - (b - a).y() * (c - a).x();
    };
    if (orientation(out) * orientation(mesh) <= 0)
      throw InvalidInput("sliding electrodes: triangle " + std::to_string(t) + " folds; the shifts are too large");
  }
  return out;
}

Sensor with_electrodes_slid(const Sensor& sensor, const std::vector<double>& shift_mm) {
  check_shifts(sensor, shift_mm);
  Sensor out = sensor;
  for (std::size_t e = 0; e < out.electrodes.size(); ++e) {
    Electrode& electrode = out.electrodes[e];
    electrode.center_s_mm = wrap_arclength(electrode.center_s_mm + shift_mm[e], sensor.border->length_mm());
    electrode.center_mm = sensor.border->point_at(electrode.center_s_mm);
  }
  return out;
}

void SlideOptions::validate() const {
  option_check::non_negative("SlideOptions", "rigid_mm", rigid_mm);
  option_check::positive("SlideOptions", "reach_mm", reach_mm);
}
}  // namespace emit
