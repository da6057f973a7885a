#pragma once
/// \file pressure_map.hpp
/// A pressure image as a picture: the per-element pressure drawn smooth over the mesh (N/mm², from
/// 0), with circles outlined (contacts found, or the true presses).
#include <string>
#include <vector>

#include "emit/mesh/mesh.hpp"
#include "emit/render/field_image.hpp"

namespace emit {

/// Writes the PNG (atomically). \param element_pressure  #F values [N/mm²]. \throw IoError.
void write_pressure_map(const Mesh& mesh, const Vector& element_pressure, const std::vector<Circle>& outlines,
                        const std::string& title, const std::string& path);

}  // namespace emit
