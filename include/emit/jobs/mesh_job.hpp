#pragma once
/// \file mesh_job.hpp
/// `emit mesh`: a sensor's sheet meshed with Gmsh (the reconstruction's mesh, or the twin's finer
/// graded one) and written as a .msh file, with the mesh's quality.
#include <string>

#include "emit/mesh/mesh_quality.hpp"

namespace emit {

struct MeshJob {
  std::string sensor_path;     ///< empty: the built-in default sensor
  std::string out_path;        ///< .msh to write
  bool twin = false;           ///< the twin's finer, electrode-graded mesh
  double element_size_mm = 0;  ///< > 0: overrides the sensor's
  double max_triangles = 0;    ///< > 0: overrides the sensor's mesh.max_triangles
  int seed = 1;                ///< the twin mesh's seed
};

struct MeshReport {
  std::string sensor_name;
  MeshQuality quality;
  int electrodes = 0;
  double seconds = 0;  ///< meshing alone
};

/// \throw InvalidInput (a sheet that cannot be meshed as asked), IoError.
MeshReport run_mesh_job(const MeshJob& job);

}  // namespace emit
