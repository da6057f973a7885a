#pragma once
/// \file spherical_cap.hpp
/// A spherical cap's mesh from a flat disc's (sensor/surface.hpp): a disc of radius a meshed in the
/// plane, each node moved onto the cap keeping its direction from the axis, its distance ρ from
/// the axis becoming the polar angle θ = θ_rim ρ / a (sin θ_rim = a / R). The rim maps onto itself,
/// node for node, so the electrodes' nodes and arc lengths are the disc's; the map stretches
/// lengths by at most s = R θ_rim / a (radially everywhere, around the axis at the apex) and by
/// 1 around the rim: the disc is meshed at h / s for a cap of size h (1.16 for R = 25, a = 20).
/// Projecting vertically instead would stretch the rim's elements by 1 / cos θ_rim (1.67 there).
#include "emit/mesh/mesh.hpp"

namespace emit {

/// s = R θ_rim / a, the largest stretch of the map (≥ 1).
double spherical_cap_stretch(double sphere_radius_mm, double base_radius_mm);

/// The cap's point for the disc's point `flat_mm` (its z ignored).
Vector3 spherical_cap_point_mm(const Vector3& flat_mm, double sphere_radius_mm, double base_radius_mm);

/// Moves every node of a mesh of the disc of radius `base_radius_mm` about the z axis onto the
/// cap. Triangles keep their orientation (counter-clockwise seen from outside the sphere).
void wrap_onto_spherical_cap(Mesh& mesh, double sphere_radius_mm, double base_radius_mm);

}  // namespace emit
