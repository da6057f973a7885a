#include "triangle_estimate.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>

#include "border_breakpoints.hpp"
#include "emit/core/errors.hpp"
#include "emit/mesh/spherical_cap.hpp"
#include "emit/sensor/surface.hpp"
#include "triangle_limit.hpp"

namespace emit {

namespace detail {

namespace {

/// An equilateral triangle's area at edge h: √3/4·h².
double triangle_area_mm2(double h_mm) { return std::sqrt(3.0) / 4 * h_mm * h_mm; }

/// Gmsh sizes the inside of a homogeneous mesh from its border's pieces
/// (Mesh.MeshSizeExtendFromBoundary): a border cut finer than the element size h, by electrodes or
/// polygon points closer than it, makes the whole sheet finer, about as fine as the pieces'
/// geometric mean length g (Gmsh's counts on a 20 mm circle of 16 to 200 electrodes of 0.1 to
/// 3 mm at h = 1 mm were 0.6 to 1.6 times the area's count at g; 1,000 electrodes of 0.1 mm on the
/// dome took over a gigabyte and minutes). The estimate adds (h/g)² − 1 times the area's count at h
/// this many times: 0.8 to 2.4 times Gmsh's count on those circles and on 60 mm squares.
constexpr double crowding_weight = 1.5;

/// The triangles the grading into an electrode's end adds beyond the homogeneous mesh's, for a
/// size factor f (mesh/gmsh/gmsh_mesh_sheet.cpp: h·f within h/2 of the end, rising linearly to h
/// at 4h): ∫ πr dr / (√3/4·size(r)²) over the half disc of radius 4h inside the sheet, less that
/// half disc at h. Independent of h: 108 for f = 1/4.
double graded_triangles_per_end(double f) {
  if (f >= 1) return 0;
  const double inner = 0.5, outer = 4;                                         // in units of h
  const double slope = (1 - f) / (outer - inner), offset = f - slope * inner;  // size(r) = offset + slope·r
  const auto primitive = [&](double r) {                                       // ∫ r / (offset + slope r)² dr
    const double size = offset + slope * r;
    return (std::log(size) + offset / size) / (slope * slope);
  };
  const double k = std::numbers::pi / triangle_area_mm2(1);
  const double core = k * inner * inner / 2 / (f * f);
  const double ring = k * (primitive(outer) - primitive(inner));
  return core + ring - k * outer * outer / 2;
}

}  // namespace

TriangleEstimate estimate_triangles(const Sensor& sensor, const MeshOptions& options) {
  TriangleEstimate estimate;
  const Shape& shape = sensor.shape;
  if (shape.kind == ShapeKind::mesh_file && !shape.surface) return estimate;  // a CAD file is checked once read
  // A cap is meshed as its disc at a finer size (mesh/spherical_cap.hpp): the disc's count.
  const bool cap = shape.kind == ShapeKind::spherical_cap;
  const double h_mm = cap ? options.element_size_mm / spherical_cap_stretch(shape.sphere_radius_mm, shape.radius_mm)
                          : options.element_size_mm;
  const double area_mm2 = cap ? std::numbers::pi * shape.radius_mm * shape.radius_mm : surface_area_mm2(shape);
  estimate.area_triangles = area_mm2 / triangle_area_mm2(h_mm);
  estimate.triangles = estimate.area_triangles;
  if (!sensor.border) return estimate;
  // The border as Gmsh cuts it: each stretch between breakpoints into pieces of at most h.
  const Border& border = *sensor.border;
  const auto points = border_breakpoints(border, sensor.electrodes);
  double log_sum = 0;
  for (std::size_t i = 0; i < points.size(); ++i) {
    const double end_mm = i + 1 < points.size() ? points[i + 1].s_mm : points[0].s_mm + border.length_mm();
    const double stretch_mm = end_mm - points[i].s_mm;
    if (!(stretch_mm > 0)) continue;
    const double pieces = std::max(1.0, std::ceil(stretch_mm / h_mm - 1e-9));
    estimate.border_pieces += pieces;
    log_sum += pieces * std::log(stretch_mm / pieces);
  }
  estimate.border_piece_mm = estimate.border_pieces > 0 ? std::exp(log_sum / estimate.border_pieces) : h_mm;
  // A graded mesh is sized by its field, not from its border (mesh/gmsh/gmsh_mesh_sheet.cpp):
  // the border's pieces refine it only near them, and the grading into the ends is counted instead:
  // each end's graded half disc, at most a band 4h wide along the border graded throughout (ends
  // closer than 8h share theirs).
  const double f = options.electrode_edge_size_factor;
  if (f >= 1) {
    const double crowding = std::pow(h_mm / std::min(h_mm, estimate.border_piece_mm), 2);
    estimate.triangles = estimate.area_triangles * (1 + crowding_weight * (crowding - 1));
  } else {
    const double ends = 2.0 * static_cast<double>(sensor.electrodes.size());
    const double band_mm2 = border.length_mm() * 4 * h_mm;
    const double band = band_mm2 / triangle_area_mm2(h_mm * f) - band_mm2 / triangle_area_mm2(h_mm);
    estimate.graded_triangles = std::min(ends * graded_triangles_per_end(f), band);
    estimate.triangles += estimate.graded_triangles;
  }
  return estimate;
}

void check_triangle_estimate(const Sensor& sensor, const MeshOptions& options) {
  const TriangleEstimate estimate = estimate_triangles(sensor, options);
  if (estimate.triangles <= options.max_triangles) return;
  const std::string meshing = "meshing " + (sensor.name.empty() ? std::string("the sensor") : sensor.name) +
                              ": about " + short_number(estimate.triangles) + " triangles at " +
                              short_number(options.element_size_mm) + " mm, ";
  // The border's pieces make most of it: a larger element size does not help, fewer pieces do.
  if (estimate.triangles > 2 * (estimate.area_triangles + estimate.graded_triangles))
    throw InvalidInput(
        meshing + "as its border is cut into " + std::to_string(static_cast<long long>(estimate.border_pieces)) +
        " pieces (between corners and electrode ends) of " + short_number(estimate.border_piece_mm) +
        " mm on average and Gmsh meshes the sheet as fine, " +
        beyond_triangle_limit(options.max_triangles, "use fewer or wider-spaced electrodes, or fewer polygon points"));
  throw InvalidInput(meshing + beyond_triangle_limit(options.max_triangles, "choose a larger element size"));
}

void check_cad_triangle_estimate(const Sensor& sensor, const MeshOptions& options, double area_mm2) {
  const double triangles = area_mm2 / triangle_area_mm2(options.element_size_mm);
  if (triangles <= options.max_triangles) return;
  throw InvalidInput("meshing " + (sensor.name.empty() ? std::string("the sensor") : sensor.name) + ": about " +
                     short_number(triangles) + " triangles at " + short_number(options.element_size_mm) + " mm, " +
                     beyond_triangle_limit(options.max_triangles, "choose a larger element size"));
}

}  // namespace detail

double estimated_triangle_count(const Sensor& sensor, const MeshOptions& options) {
  return detail::estimate_triangles(sensor, options).triangles;
}

}  // namespace emit
