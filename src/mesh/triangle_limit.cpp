#include "triangle_limit.hpp"

#include <cstdio>

namespace emit::detail {

std::string short_number(double value) {
  char text[32];
  std::snprintf(text, sizeof text, "%.3g", value);
  return text;
}

std::string beyond_triangle_limit(double max_triangles, const std::string& advice) {
  return "beyond the limit of " + short_number(max_triangles) + " triangles: " + advice +
         ", or raise the limit (sensor \"mesh\": {\"max_triangles\": N}, or emit mesh --max-triangles N)";
}

}  // namespace emit::detail
