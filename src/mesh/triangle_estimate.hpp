#pragma once
// Private to mesh/ (and its Gmsh module): how many triangles Gmsh will make of a sheet, estimated
// before it meshes (generate_mesh.hpp estimated_triangle_count), and the refusal beyond
// MeshOptions::max_triangles, saying what to change.
#include "emit/mesh/generate_mesh.hpp"
#include "emit/sensor/sensor.hpp"

namespace emit::detail {

/// The estimate and what it is made of.
struct TriangleEstimate {
  double triangles = 0;
  /// The sheet's area over an equilateral triangle's at the element size (the whole estimate of
  /// a sheet whose border Gmsh cuts into pieces near the element size).
  double area_triangles = 0;
  /// The border's pieces as Gmsh cuts them: each stretch between corners and electrode ends cut
  /// into pieces of at most the element size; their count and geometric mean length.
  double border_pieces = 0;
  double border_piece_mm = 0;
  /// The triangles the grading into the electrodes' ends adds (MeshOptions::electrode_edge_size_factor).
  double graded_triangles = 0;
};

/// The estimate for a drawn sheet (or a file's surface by its area; 0 for CAD, read first).
TriangleEstimate estimate_triangles(const Sensor& sensor, const MeshOptions& options);

/// \throw InvalidInput when estimate_triangles is beyond options.max_triangles: the estimate, the
/// limit, and what brings it down (a larger element size; fewer or wider-spaced electrodes, or
/// fewer polygon points, when the border's pieces are what makes it) or raises the limit.
void check_triangle_estimate(const Sensor& sensor, const MeshOptions& options);

/// The same for a CAD sheet, once its surfaces' area is known (the module reads it).
void check_cad_triangle_estimate(const Sensor& sensor, const MeshOptions& options, double area_mm2);

}  // namespace emit::detail
