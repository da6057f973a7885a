// The sheet drawn and meshed with Gmsh's geometry kernel, or a CAD file's surfaces through
// OpenCASCADE: the module's half of generate_mesh (mesh/generate_mesh.hpp, ../gmsh_mesher.hpp).
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <stdexcept>

#include <gmsh.h>

#include "border_breakpoints.hpp"
#include "cad_sheet.hpp"
#include "emit/core/errors.hpp"
#include "emit/mesh/cylinder.hpp"
#include "emit/sensor/surface.hpp"
#include "gmsh_mesher.hpp"
#include "gmsh_session.hpp"
#include "triangle_estimate.hpp"

namespace emit::detail {

namespace {

/// The electrode whose interval holds arc length s, or -1.
int electrode_at(const Border& border, const std::vector<Electrode>& electrodes, double s_mm) {
  for (int e = 0; e < static_cast<int>(electrodes.size()); ++e) {
    const double from_start =
        wrap_arclength(s_mm - (electrodes[e].center_s_mm - 0.5 * electrodes[e].width_mm), border.length_mm());
    if (from_start < electrodes[e].width_mm) return e;
  }
  return -1;
}

const BorderPiece& piece_holding(const Border& border, double s_mm) {
  const auto& pieces = border.pieces();
  for (std::size_t i = pieces.size(); i-- > 0;)
    if (s_mm >= pieces[i].start_s_mm) return pieces[i];
  return pieces.front();
}

/// A sleeve's chart (sensor/surface.hpp) is the rectangle [0, L] × [0, 2πR] whose edges v = 0 and
/// v = 2πR are one seam: the top edge's mesh is the bottom's moved by 2πR along v, so that
/// wrap_onto_cylinder can merge their nodes. Its curves are the border's first and third pieces
/// (Border::rectangle), each a single curve: a sleeve's electrodes lie on its rims
/// (validate_sleeve_electrodes).
void make_seam_periodic(const Sensor& sensor, const std::vector<int>& curve_tags,
                        const std::vector<double>& curve_middle_s_mm) {
  const auto& pieces = sensor.border->pieces();
  const auto curve_on = [&](const BorderPiece& piece) {
    std::vector<int> found;
    for (std::size_t c = 0; c < curve_tags.size(); ++c)
      if (curve_middle_s_mm[c] > piece.start_s_mm && curve_middle_s_mm[c] < piece.start_s_mm + piece.length_mm)
        found.push_back(curve_tags[c]);
    if (found.size() != 1) throw std::logic_error("make_seam_periodic: a seam edge is not one curve");
    return found.front();
  };
  const double round_mm = pieces[1].length_mm;
  // The affine map from the bottom edge (the master) to the top, row-major 4 × 4: a translation.
  const std::vector<double> shift{1, 0, 0, 0, 0, 1, 0, round_mm, 0, 0, 1, 0, 0, 0, 0, 1};
  gmsh::model::mesh::setPeriodic(1, {curve_on(pieces[2])}, {curve_on(pieces[0])}, shift);
}

/// Build the sheet's geometry in Gmsh's built-in kernel: points, curves (one per border stretch
/// between breakpoints), one plane surface, and a physical curve group per electrode.
void build_geometry(const Sensor& sensor, const MeshOptions& options, std::vector<int>& electrode_end_tags) {
  const Border& border = *sensor.border;
  const auto breakpoints = border_breakpoints(border, sensor.electrodes);
  const double h = options.element_size_mm;
  const bool sleeve = is_sleeve(sensor.shape);
  const double round_mm = 2 * std::numbers::pi * sensor.shape.radius_mm;
  std::vector<int> point_tags;
  for (const auto& b : breakpoints) {
    const Vector2 p = border.point_at(b.s_mm);
    point_tags.push_back(gmsh::model::geo::addPoint(p.x(), p.y(), 0, h));
    if (!b.electrode_end) continue;
    electrode_end_tags.push_back(point_tags.back());
    // On a sleeve an end near the seam is near the chart's other edge too: its twin there, a point
    // on no curve, grades the mesh on that side as well (grade_into_electrode_ends reaches 4h).
    if (sleeve && p.y() < 4 * h)
      electrode_end_tags.push_back(gmsh::model::geo::addPoint(p.x(), p.y() + round_mm, 0, h));
    if (sleeve && p.y() > round_mm - 4 * h)
      electrode_end_tags.push_back(gmsh::model::geo::addPoint(p.x(), p.y() - round_mm, 0, h));
  }
  int center_tag = -1;
  std::vector<int> curve_tags;
  std::vector<double> curve_middle_s_mm;
  std::vector<std::vector<int>> electrode_curves(sensor.electrodes.size());
  const std::size_t n = breakpoints.size();
  for (std::size_t i = 0; i < n; ++i) {
    const double s0 = breakpoints[i].s_mm;
    const double s1 = i + 1 < n ? breakpoints[i + 1].s_mm : border.length_mm();
    const BorderPiece& piece = piece_holding(border, 0.5 * (s0 + s1));
    const int a = point_tags[i], b = point_tags[(i + 1) % n];
    int curve;
    if (piece.kind == BorderPiece::Kind::line) {
      curve = gmsh::model::geo::addLine(a, b);
    } else {
      if (center_tag < 0)
        center_tag = gmsh::model::geo::addPoint(piece.arc_center_mm.x(), piece.arc_center_mm.y(), 0, h);
      curve = gmsh::model::geo::addCircleArc(a, center_tag, b);
    }
    curve_tags.push_back(curve);
    curve_middle_s_mm.push_back(0.5 * (s0 + s1));
    const int e = electrode_at(border, sensor.electrodes, 0.5 * (s0 + s1));
    if (e >= 0) electrode_curves[e].push_back(curve);
  }
  const int loop = gmsh::model::geo::addCurveLoop(curve_tags);
  const int surface = gmsh::model::geo::addPlaneSurface({loop});
  gmsh::model::geo::synchronize();
  if (sleeve) make_seam_periodic(sensor, curve_tags, curve_middle_s_mm);
  for (std::size_t e = 0; e < electrode_curves.size(); ++e) {
    const int group = gmsh::model::addPhysicalGroup(1, electrode_curves[e]);
    gmsh::model::setPhysicalName(1, group, "electrode " + std::to_string(e));
  }
  gmsh::model::setPhysicalName(2, gmsh::model::addPhysicalGroup(2, {surface}), "sheet");
}

/// Grade the size from h·factor at the electrodes' ends to h a few elements away (a Distance +
/// Threshold background field). Only the neighbourhood of the ends is refined: sizes are not
/// extended from the border into the sheet.
void grade_into_electrode_ends(const std::vector<int>& end_points, const MeshOptions& options) {
  namespace field = gmsh::model::mesh::field;
  const double h = options.element_size_mm;
  const int distance = field::add("Distance");
  field::setNumbers(distance, "PointsList", std::vector<double>(end_points.begin(), end_points.end()));
  const int threshold = field::add("Threshold");
  field::setNumber(threshold, "InField", distance);
  field::setNumber(threshold, "SizeMin", h * options.electrode_edge_size_factor);
  field::setNumber(threshold, "SizeMax", h);
  field::setNumber(threshold, "DistMin", 0.5 * h);
  field::setNumber(threshold, "DistMax", 4.0 * h);
  field::setAsBackgroundMesh(threshold);
  gmsh::option::setNumber("Mesh.MeshSizeExtendFromBoundary", 0);
}

}  // namespace

Mesh gmsh_mesh_sheet(const Sensor& sensor, const MeshOptions& flat) {
  const bool cad = sensor.shape.kind == ShapeKind::mesh_file && is_cad_file(sensor.shape.mesh_path);
  GmshSession gmsh_session;
  const std::string context = "meshing " + (sensor.name.empty() ? std::string("the sensor") : sensor.name);
  gmsh_session.run<InvalidInput>(context, [&] {
    gmsh::model::add("sheet");
    gmsh::option::setNumber("Mesh.Algorithm", 6);  // Frontal-Delaunay: near-equilateral triangles
    gmsh::option::setNumber("Mesh.Smoothing", flat.smoothing_steps);
    gmsh::option::setNumber("Mesh.MeshSizeFromPoints", 1);
    gmsh::option::setNumber("Mesh.MeshSizeExtendFromBoundary", 1);
    gmsh::option::setNumber("Mesh.MeshSizeMax", flat.element_size_mm);
    gmsh::option::setNumber("Mesh.RandomSeed", flat.seed);
    // The seed only moves Gmsh's tiny random perturbations; a slightly different start size
    // makes seeds give visibly different meshes of the same density.
    gmsh::option::setNumber("Mesh.MeshSizeFactor", 1.0 + 0.01 * (flat.seed % 7));
    std::vector<int> electrode_ends;
    if (cad) {
      // A CAD surface's area is known once read: its estimate is checked before meshing.
      const double area_mm2 = import_cad_sheet(sensor, electrode_ends);
      check_cad_triangle_estimate(sensor, flat, area_mm2);
    } else {
      build_geometry(sensor, flat, electrode_ends);
    }
    if (flat.electrode_edge_size_factor < 1) grade_into_electrode_ends(electrode_ends, flat);
    gmsh::model::mesh::generate(2);
  });
  return gmsh_session.extract_mesh(context);
}

}  // namespace emit::detail
