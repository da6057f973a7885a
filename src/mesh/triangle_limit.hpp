#pragma once
// Private to mesh/: the words every refusal beyond MeshOptions::max_triangles ends with, so that a
// user hears the same way out whether the count was estimated or read from a file.
#include <string>

namespace emit::detail {

/// "beyond the limit of 1e+06 triangles: <advice>, or raise the limit (sensor "mesh":
/// {"max_triangles": N}, or emit mesh --max-triangles N)".
std::string beyond_triangle_limit(double max_triangles, const std::string& advice);

/// A number as "%.3g" writes it: "1.2e+06", "0.45".
std::string short_number(double value);

}  // namespace emit::detail
