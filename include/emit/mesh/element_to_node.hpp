#pragma once
/// \file element_to_node.hpp
/// Per-element values → per-node values, each node the area-weighted mean of its triangles
/// (for pictures: a P0 image drawn as a smooth P1 field).
#include "emit/mesh/mesh.hpp"

namespace emit {

Vector element_to_node(const Mesh& mesh, const Vector& element_values);

}  // namespace emit
