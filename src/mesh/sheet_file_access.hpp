#pragma once
// Private to mesh/ (and its Gmsh module): whether a sheet's file (a .msh, an STL, CAD) can be
// opened, said in one line before anything reads it.
#include <string>

namespace emit::detail {

/// Checks that `path` names a regular file that can be read. `kind` names the file in the
/// messages ("STL file", "mesh file", "CAD file").
/// \throw InvalidInput when the name is too long for the file system (the message quotes its start
/// and says how long it is); IoError "<path>: no such <kind>" or "cannot read <kind> (<reason>)".
void check_sheet_file_access(const std::string& path, const std::string& kind);

}  // namespace emit::detail
