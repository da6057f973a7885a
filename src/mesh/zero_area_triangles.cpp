#include "zero_area_triangles.hpp"

#include <algorithm>
#include <cstdio>

#include "emit/core/errors.hpp"

namespace emit::detail {

namespace {

constexpr double zero_area_fraction = 1e-12;

std::string point_text(const Vector3& p) {
  char text[96];
  std::snprintf(text, sizeof text, "(%.6g, %.6g, %.6g)", p.x(), p.y(), p.z());
  return text;
}

}  // namespace

bool has_zero_area(const Vector3& a, const Vector3& b, const Vector3& c) {
  const double longest_mm2 = std::max({(b - a).squaredNorm(), (c - b).squaredNorm(), (a - c).squaredNorm()});
  return (b - a).cross(c - a).norm() <= zero_area_fraction * longest_mm2;
}

std::string zero_area_corners_text(const Vector3& a, const Vector3& b, const Vector3& c) {
  const bool repeat = a == b || b == c || c == a;
  return point_text(a) + ", " + point_text(b) + ", " + point_text(c) +
         (repeat ? " repeat a point" : " lie on one line");
}

void refuse_zero_area_triangles(const Mesh& mesh, const std::string& file) {
  for (Index t = 0; t < mesh.triangle_count(); ++t) {
    const Vector3 a = mesh.nodes_mm.row(mesh.triangles(t, 0)), b = mesh.nodes_mm.row(mesh.triangles(t, 1)),
                  c = mesh.nodes_mm.row(mesh.triangles(t, 2));
    if (!a.allFinite() || !b.allFinite() || !c.allFinite())
      throw InvalidInput(file + ": a triangle with a corner that is not a finite number: " + point_text(a) + ", " +
                         point_text(b) + ", " + point_text(c));
    if (has_zero_area(a, b, c))
      throw InvalidInput(file + ": a triangle of zero area: its corners " + zero_area_corners_text(a, b, c));
  }
}

}  // namespace emit::detail
