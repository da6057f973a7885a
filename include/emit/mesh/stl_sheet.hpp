#pragma once
/// \file stl_sheet.hpp
/// A sheet read from an STL surface (README "Sensor description", shape "mesh"): its triangles are
/// the mesh as they are (the twin's and the reconstruction's alike), and each electrode is the
/// stretch of its border of the given width centred on the border's point nearest the given one.
#include "emit/mesh/mesh.hpp"
#include "emit/sensor/sensor.hpp"

namespace emit {

/// Read sensor.shape.mesh_path (ASCII or binary STL, checked by emit first, stl_file_check.hpp: at
/// most sensor.mesh.max_triangles triangles, finite corners, none of zero area; then read by Gmsh,
/// which merges its repeated vertices), split the border's edges at every electrode's ends so that
/// each electrode is an exact set of border edges (electrode_width_mm[i] long along the border, in
/// 3D), and number the mesh for locality.
/// \throw IoError for a missing file; InvalidInput naming the file for one that is not STL or fails
/// those checks, a surface whose border is not one loop, an electrode point more than 0.5 mm from
/// the border, an electrode longer than the border or two that overlap.
Mesh read_stl_sheet(const Sensor& sensor);

}  // namespace emit
