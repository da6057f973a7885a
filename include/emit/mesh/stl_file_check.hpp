#pragma once
/// \file stl_file_check.hpp
/// An STL file checked before Gmsh reads it (mesh/stl_sheet.hpp). Gmsh's reader trusts its input:
/// one NaN vertex fails an assertion inside it and aborts the process, a binary header's count
/// sizes its allocation, and it reads ASCII by position, one keyword a line. So emit reads the file
/// itself first, holding one line or one triangle at a time, and refuses what Gmsh would not read
/// as written, in one line naming the file and the triangle.
#include <cstdint>
#include <string>

namespace emit {

/// What check_stl_file found.
struct StlFileSummary {
  bool binary = false;
  std::int64_t triangle_count = 0;
};

/// Reads the STL file at `path` and checks it: ASCII ("solid", then each triangle as "facet …",
/// "outer loop", three "vertex x y z", "endloop", "endfacet", one a line, then "endsolid"; lines
/// of at most 254 bytes, as Gmsh's reader takes them) or binary (an 80-byte header, the count,
/// 50 bytes a triangle and nothing after: a file whose header begins with "solid" is binary only
/// if Gmsh's text reading would find no vertex in it). Every coordinate must be a finite number,
/// no triangle may have zero area (two corners at one point, or three on one line), and there must
/// be at least one triangle and at most `max_triangles`: a binary file's count is taken from its
/// header before any triangle is read; an ASCII file is refused as soon as it passes the limit.
/// Memory does not grow with the file.
/// \throw IoError for a file that is missing or cannot be read; InvalidInput naming the file and
/// what is wrong: the triangle (numbered from 0; in ASCII with its line) or the line.
StlFileSummary check_stl_file(const std::string& path, double max_triangles);

}  // namespace emit
