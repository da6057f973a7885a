#pragma once
// Private to mesh/: triangles of zero area, which a sheet's file must not hold (the stiffness of
// such a triangle divides by its area): the test, and the check of a mesh read from a file.
#include <string>

#include "emit/core/types.hpp"
#include "emit/mesh/mesh.hpp"

namespace emit::detail {

/// Whether triangle abc has zero area: twice its area is below 1e-12 of its longest edge squared,
/// so its smallest angle is below 1e-12 rad, far below any mesh's and far above rounding (1e-16).
/// True for corners that repeat a point or lie on one line.
bool has_zero_area(const Vector3& a, const Vector3& b, const Vector3& c);

/// "(x, y, z), (x, y, z), (x, y, z) repeat a point" or "… lie on one line", for a message.
std::string zero_area_corners_text(const Vector3& a, const Vector3& b, const Vector3& c);

/// \throw InvalidInput "<file>: a triangle of zero area: its corners …" for the first such triangle
/// of `mesh`, or one with a corner that is not a finite number.
void refuse_zero_area_triangles(const Mesh& mesh, const std::string& file);

}  // namespace emit::detail
