// An STL sheet read by Gmsh (mesh/stl_sheet.hpp read_stl_sheet, through ../gmsh_mesher.hpp).
#include <algorithm>
#include <cstdio>
#include <limits>

#include <gmsh.h>

#include "emit/core/errors.hpp"
#include "emit/core/quote_input.hpp"
#include "emit/mesh/sort_for_locality.hpp"
#include "emit/sensor/border.hpp"
#include "emit/sensor/height_field.hpp"
#include "gmsh_mesher.hpp"
#include "gmsh_session.hpp"
#include "sheet_file_access.hpp"

namespace emit::detail {

namespace {

/// How far from the border an electrode's point may be: a point read off a drawing.
constexpr double electrode_point_tolerance_mm = 0.5;

/// The border as a closed polyline of nodes with the arc length (3D) at each.
struct BorderLoop {
  std::vector<int> nodes;
  std::vector<double> s_mm;  ///< at nodes[k]; the loop closes at length_mm
  double length_mm = 0;
};

BorderLoop border_of(const Mesh& mesh, const std::string& file) {
  const auto loop = border_loop(mesh.triangles);
  if (!loop) throw InvalidInput(file + ": the surface's border is not one closed loop (holes, or several pieces)");
  BorderLoop b;
  b.nodes = *loop;
  for (std::size_t k = 0; k < b.nodes.size(); ++k) {
    b.s_mm.push_back(b.length_mm);
    b.length_mm += (mesh.nodes_mm.row(b.nodes[(k + 1) % b.nodes.size()]) - mesh.nodes_mm.row(b.nodes[k])).norm();
  }
  return b;
}

/// The arc length of the border's point nearest p, and how far it is.
std::pair<double, double> nearest_on_border(const Mesh& mesh, const BorderLoop& b, const Vector3& p) {
  double best_s = 0, best_mm = std::numeric_limits<double>::infinity();
  for (std::size_t k = 0; k < b.nodes.size(); ++k) {
    const Vector3 a = mesh.nodes_mm.row(b.nodes[k]), c = mesh.nodes_mm.row(b.nodes[(k + 1) % b.nodes.size()]);
    const double t = std::clamp((p - a).dot(c - a) / (c - a).squaredNorm(), 0.0, 1.0);
    const double distance = (a + t * (c - a) - p).norm();
    if (distance < best_mm) best_mm = distance, best_s = b.s_mm[k] + t * (c - a).norm();
  }
  return {best_s, best_mm};
}

/// A node of the border at arc length s: an existing one within a micrometre, else a new one on
/// its edge, the triangle on that edge split in two (orientation kept).
int node_at(Mesh& mesh, BorderLoop& b, double s_mm) {
  const std::size_t n = b.nodes.size();
  std::size_t k = n - 1;
  while (k > 0 && b.s_mm[k] > s_mm) --k;
  const double next_s = k + 1 < n ? b.s_mm[k + 1] : b.length_mm;
  if (s_mm - b.s_mm[k] < 1e-3) return b.nodes[k];
  if (next_s - s_mm < 1e-3) return b.nodes[(k + 1) % n];
  const int a = b.nodes[k], c = b.nodes[(k + 1) % n];
  const double t = (s_mm - b.s_mm[k]) / (next_s - b.s_mm[k]);
  const auto p = static_cast<int>(mesh.node_count());
  mesh.nodes_mm.conservativeResize(p + 1, 3);
  mesh.nodes_mm.row(p) = (1 - t) * mesh.nodes_mm.row(a) + t * mesh.nodes_mm.row(c);
  for (Index f = 0; f < mesh.triangle_count(); ++f)
    for (int j = 0; j < 3; ++j) {
      const int u = mesh.triangles(f, j), v = mesh.triangles(f, (j + 1) % 3), w = mesh.triangles(f, (j + 2) % 3);
      if (!((u == a && v == c) || (u == c && v == a))) continue;
      mesh.triangles.row(f) << u, p, w;  // (u, v, w) → (u, p, w) and (p, v, w)
      mesh.triangles.conservativeResize(mesh.triangle_count() + 1, 3);
      mesh.triangles.row(mesh.triangle_count() - 1) << p, v, w;
      b.nodes.insert(b.nodes.begin() + static_cast<std::ptrdiff_t>(k) + 1, p);
      b.s_mm.insert(b.s_mm.begin() + static_cast<std::ptrdiff_t>(k) + 1, s_mm);
      return p;
    }
  throw std::logic_error("read_stl_sheet: a border edge on no triangle");
}

}  // namespace

Mesh gmsh_read_stl_sheet(const Sensor& sensor) {
  const std::string& path = sensor.shape.mesh_path;
  const std::string file = quote_input(path, 120);
  check_sheet_file_access(path, "STL file");
  GmshSession gmsh_session;
  gmsh_session.run<InvalidInput>(file + ": not a valid STL file", [&] { gmsh::merge(path); });
  Mesh mesh = gmsh_session.extract_mesh(file, /*electrodes_required=*/false);
  BorderLoop border = border_of(mesh, file);
  const auto& at = sensor.shape.electrode_at_mm;
  const auto& width = sensor.shape.electrode_width_mm;
  // Each electrode's stretch [start, start + width] of the border, by arc length.
  std::vector<double> start_mm(at.size());
  for (std::size_t e = 0; e < at.size(); ++e) {
    const auto [s_mm, off_mm] = nearest_on_border(mesh, border, at[e]);
    char where[160];
    std::snprintf(where, sizeof where, ": electrode %zu at (%.4g, %.4g, %.4g) mm", e, at[e].x(), at[e].y(), at[e].z());
    if (off_mm > electrode_point_tolerance_mm) {
      char text[96];
      std::snprintf(text, sizeof text, " is %.3g mm from the border (at most %.1f)", off_mm,
                    electrode_point_tolerance_mm);
      throw InvalidInput(file + where + text);
    }
    if (width[e] >= border.length_mm) throw InvalidInput(file + where + ": wider than the whole border");
    start_mm[e] = wrap_arclength(s_mm - width[e] / 2, border.length_mm);
  }
  for (std::size_t e = 0; e < at.size(); ++e)
    for (std::size_t f = e + 1; f < at.size(); ++f) {
      const double gap = wrap_arclength(start_mm[f] - start_mm[e], border.length_mm);
      if (gap < width[e] || border.length_mm - gap < width[f])
        throw InvalidInput(file + ": electrodes " + std::to_string(e) + " and " + std::to_string(f) + " overlap");
    }
  // Split the border at every end, then take each stretch's nodes.
  for (std::size_t e = 0; e < at.size(); ++e) {
    node_at(mesh, border, start_mm[e]);
    node_at(mesh, border, wrap_arclength(start_mm[e] + width[e], border.length_mm));
  }
  for (std::size_t e = 0; e < at.size(); ++e) {
    std::vector<int> nodes;
    for (std::size_t k = 0; k < border.nodes.size(); ++k)
      if (wrap_arclength(border.s_mm[k] - start_mm[e], border.length_mm) <= width[e] + 1e-3 ||
          wrap_arclength(start_mm[e] - border.s_mm[k], border.length_mm) <= 1e-3)
        nodes.push_back(border.nodes[k]);
    std::sort(nodes.begin(), nodes.end());
    mesh.electrode_nodes.push_back(nodes);
  }
  return sort_for_locality(mesh);
}

}  // namespace emit::detail
