#include "cad_sheet.hpp"

#include <cstdio>
#include <limits>

#include <gmsh.h>

#include "emit/core/errors.hpp"
#include "emit/core/quote_input.hpp"
#include "sheet_file_access.hpp"

namespace emit::detail {

namespace {

/// How far from its border curve an electrode's point may be: a point read off a drawing.
constexpr double electrode_point_tolerance_mm = 0.5;

std::string point_text(const Vector3& p) {
  char text[96];
  std::snprintf(text, sizeof text, "(%.4g, %.4g, %.4g) mm", p.x(), p.y(), p.z());
  return text;
}

}  // namespace

double import_cad_sheet(const Sensor& sensor, std::vector<int>& electrode_end_tags) {
  const std::string file = quote_input(sensor.shape.mesh_path, 120);
  // emit has read a STEP file itself first (mesh/step_file_check.hpp, from generate_mesh).
  check_sheet_file_access(sensor.shape.mesh_path, "CAD file");
  // A STEP file from Gmsh (or many CAD tools) writes each face as its own part, its shared edges
  // twice: sewn, the faces share them, and the mesh is one sheet. The file's numbers are taken as
  // mm (Geometry.OCCTargetUnit left empty: no conversion).
  gmsh::option::setNumber("Geometry.OCCSewFaces", 1);
  gmsh::merge(sensor.shape.mesh_path);
  gmsh::vectorpair surfaces, border;
  gmsh::model::getEntities(surfaces, 2);
  if (surfaces.empty()) throw InvalidInput(file + ": the CAD file holds no surface to be the sheet");
  gmsh::vectorpair solids;
  gmsh::model::getEntities(solids, 3);
  if (!solids.empty())
    throw InvalidInput(file + ": the CAD file holds a solid; export only the skin's faces (the sheet is a surface)");
  // The outer border: the curves that bound exactly one of the surfaces.
  gmsh::model::getBoundary(surfaces, border, /*combined=*/true, /*oriented=*/false, /*recursive=*/false);
  // A closed surface (a solid's skin, sewn from its faces, or a sphere) has no border at all.
  if (border.empty())
    throw InvalidInput(file +
                       ": the CAD surface is closed (a solid's skin, or a closed shell): it has no open border "
                       "for the electrodes; the sheet must be an open surface, its border where the skin ends: "
                       "export only the skin's faces");
  std::vector<int> taken(sensor.shape.electrode_at_mm.size(), -1);
  for (std::size_t e = 0; e < sensor.shape.electrode_at_mm.size(); ++e) {
    const Vector3& at = sensor.shape.electrode_at_mm[e];
    int nearest = -1;
    double nearest_mm = std::numeric_limits<double>::infinity();
    for (const auto& [dim, tag] : border) {
      std::vector<double> closest, parametric;
      gmsh::model::getClosestPoint(dim, tag, {at.x(), at.y(), at.z()}, closest, parametric);
      const double distance_mm = (Vector3(closest[0], closest[1], closest[2]) - at).norm();
      if (distance_mm < nearest_mm) nearest_mm = distance_mm, nearest = tag;
    }
    const std::string where = file + ": electrode " + std::to_string(e) + " at " + point_text(at);
    if (nearest < 0 || nearest_mm > electrode_point_tolerance_mm) {
      char text[96];
      std::snprintf(text, sizeof text, ": no border curve within %.1f mm (the nearest is %.3g mm away)",
                    electrode_point_tolerance_mm, nearest_mm);
      throw InvalidInput(where + text + "; split the CAD border where the electrodes end");
    }
    for (std::size_t other = 0; other < e; ++other)
      if (taken[other] == nearest)
        throw InvalidInput(where + ": names the same border curve as electrode " + std::to_string(other));
    taken[e] = nearest;
    gmsh::model::setPhysicalName(1, gmsh::model::addPhysicalGroup(1, {nearest}), "electrode " + std::to_string(e));
    gmsh::vectorpair ends;
    gmsh::model::getBoundary({{1, nearest}}, ends, false, false, false);
    for (const auto& end : ends) electrode_end_tags.push_back(end.second);
  }
  std::vector<int> surface_tags;
  double area_mm2 = 0;
  for (const auto& s : surfaces) {
    surface_tags.push_back(s.second);
    double face_mm2 = 0;
    gmsh::model::occ::getMass(2, s.second, face_mm2);
    area_mm2 += face_mm2;
  }
  gmsh::model::setPhysicalName(2, gmsh::model::addPhysicalGroup(2, surface_tags), "sheet");
  return area_mm2;
}

}  // namespace emit::detail
