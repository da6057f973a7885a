#pragma once
// Private to mesh/ (and its Gmsh module): where a drawn sheet's border must have a mesh node, so
// that Gmsh is given one curve from each to the next (mesh/gmsh/gmsh_mesh_sheet.cpp), and the
// triangle estimate knows the pieces Gmsh will cut the border into (generate_mesh.cpp).
#include <vector>

#include "emit/sensor/sensor.hpp"

namespace emit::detail {

/// A point where the border mesh must have a node: a corner, a quarter of a circle, or an
/// electrode's end.
struct Breakpoint {
  double s_mm;
  bool electrode_end;
};

/// The border's breakpoints in order of arc length from 0, those closer than 1e-9 of the border
/// merged (an electrode ending on a corner).
std::vector<Breakpoint> border_breakpoints(const Border& border, const std::vector<Electrode>& electrodes);

}  // namespace emit::detail
