#pragma once
/// \file msh_file_check.hpp
/// A Gmsh .msh file checked before Gmsh reads it (mesh/mesh_io.hpp): Gmsh's reader sizes its
/// tables by the counts a file's headers claim and takes any number for a coordinate, so emit reads
/// the file itself first, holding one value at a time, and refuses in one line naming the file and
/// the place what it would not use: a count beyond the triangle limit, a coordinate that is not a
/// finite number, a section cut short.
#include <cstdint>
#include <string>

namespace emit {

/// What check_msh_file found.
struct MshFileSummary {
  double version = 0;  ///< 2.2 or 4.1 (2, 2.1 and 2.2 are read alike)
  bool binary = false;
  std::int64_t node_count = 0;
  std::int64_t triangle_count = 0;  ///< 3-node triangles (element type 2)
};

/// Reads the .msh file at `path` (MSH 2 or 4.1, ASCII or binary, little-endian, as Gmsh writes
/// them) and checks its $Nodes and $Elements sections: the counts their headers claim agree with
/// what follows, every node's x, y and z are finite numbers, every element is of a type of the MSH
/// format, and there is at least one triangle and at most `max_triangles` (the count is taken from
/// each block's header, before its elements are read) on at most 3 × (max_triangles + 1) nodes. Other
/// sections are passed over to their "$End…" line. Memory does not grow with the file.
/// \throw IoError for a file that is missing or cannot be read; InvalidInput naming the file and
/// what is wrong where (the section, the node or element by its tag, or the line).
MshFileSummary check_msh_file(const std::string& path, double max_triangles);

}  // namespace emit
