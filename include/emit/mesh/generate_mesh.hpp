#pragma once
/// \file generate_mesh.hpp
/// Meshing a sensor's sheet with Gmsh (Frontal-Delaunay): near-equilateral triangles at a
/// requested size, with mesh nodes at both ends of every electrode so that each electrode is an
/// exact set of border edges.
#include "emit/mesh/mesh.hpp"
#include "emit/sensor/sensor.hpp"

namespace emit {

struct MeshOptions {
  double element_size_mm = 1.2;
  /// Size at the electrodes' ends as a fraction of element_size_mm. 1 gives a homogeneous mesh
  /// (the reconstruction's); < 1 grades the mesh into the ends, where the potential is singular
  /// (the twin's: it resolves the edge singularity, as the conformance frames do).
  double electrode_edge_size_factor = 1.0;
  /// Seed of Gmsh's random perturbations: another seed gives another mesh of the same size,
  /// so a twin can differ from the reconstruction's mesh.
  int seed = 0;
  /// Gmsh's Laplacian smoothing passes after meshing (Mesh.Smoothing). Frontal-Delaunay's
  /// triangles are near-equilateral without them, and the pass is a third of the meshing time:
  /// on the default sensor, 6.8k triangles 0.074 → 0.040 s, 23k 0.315 → 0.195 s, for a mean
  /// smallest angle of 57.0° → 56.7° and 59.42° → 59.41°, the smallest 38° → 33° and 36°, none
  /// below 30°. So the reconstruction's mesh skips it (reconstruction_mesh_options); graded
  /// meshes (the twin's, the contact fit's) keep Gmsh's default single pass.
  int smoothing_steps = 1;
  /// Refuse to mesh beyond this many triangles (estimated first; MeshSpec::max_triangles).
  double max_triangles = 1e6;
  void validate() const;  ///< \throw InvalidInput naming the option (core/option_check.hpp)
};

/// About how many triangles Gmsh makes for the sheet at options.element_size_mm: the sheet's area
/// over an equilateral triangle's, √3/4·h² (0 for a mesh-file sensor, which is read, not made).
double estimated_triangle_count(const Sensor& sensor, const MeshOptions& options);

/// The reconstruction mesh of a sensor as its description asks.
MeshOptions reconstruction_mesh_options(const Sensor& sensor);
/// The twin's finer, edge-graded mesh (docs/physics.md, "The digital twin": finer than the reconstruction's).
MeshOptions twin_mesh_options(const Sensor& sensor, int seed = 1);

/// Mesh the sensor's sheet; for a .msh sensor, read the file instead. A CAD sheet (STEP or IGES)
/// is read through Gmsh's OpenCASCADE kernel and meshed like a built-in shape, electrode i the
/// border curve nearest shape.electrode_at_mm[i] (within 0.5 mm). Either way the mesh comes out
/// numbered for locality (sort_for_locality.hpp).
/// \throw InvalidInput if the sheet cannot be meshed as asked or its estimated triangle count is
/// beyond options.max_triangles (the message says how to raise it); IoError for an unreadable mesh file.
Mesh generate_mesh(const Sensor& sensor, const MeshOptions& options);

}  // namespace emit
