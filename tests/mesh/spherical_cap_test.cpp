// A spherical cap's mesh: the disc's, wrapped onto the sphere (mesh/spherical_cap.hpp).
#include "emit/mesh/spherical_cap.hpp"

#include <cmath>
#include <cstdio>
#include <numbers>

#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "emit/mesh/generate_mesh.hpp"
#include "emit/mesh/mesh_quality.hpp"
#include "emit/sensor/sensor_json.hpp"
#include "emit/sensor/surface.hpp"
#include "test_support.hpp"

namespace emit {
namespace {

/// The conformance dome (tests/data/conformance/README.md): R = 25 mm, a = 20 mm, 16 electrodes of
/// 3 mm on the rim.
Sensor dome(double element_size_mm = 1.2) {
  return parse_sensor(
      nlohmann::json{{"shape", {{"type", "spherical_cap"}, {"sphere_radius_mm", 25}, {"base_radius_mm", 20}}},
                     {"electrodes", {{"count", 16}, {"width_mm", 3}}},
                     {"mesh", {{"element_size_mm", element_size_mm}}}});
}

// s = R θ_rim / a with sin θ_rim = a / R: 25 · asin(0.8) / 20; a hemisphere's π/2; a flat cap's 1.
TEST(SphericalCap, StretchOfTheMap) {
  EXPECT_NEAR(spherical_cap_stretch(25, 20), 25 * std::asin(0.8) / 20, 1e-15);
  EXPECT_NEAR(spherical_cap_stretch(20, 20), std::numbers::pi / 2, 1e-15);
  EXPECT_NEAR(spherical_cap_stretch(1e6, 20), 1.0, 1e-9);
}

// Every node on the sphere, the rim's nodes (the electrodes') in the plane z = 0 on the circle of
// radius a, the apex at R − √(R² − a²), and triangles facing out of the sphere: all to rounding.
TEST(SphericalCap, NodesLieOnTheSphereAndTheRimStays) {
  const Sensor sensor = dome();
  const Mesh mesh = generate_mesh(sensor, reconstruction_mesh_options(sensor));
  const Vector3 centre(0, 0, -15);  // √(25² − 20²) below the rim's plane
  double worst = 0, highest = 0;
  for (Index v = 0; v < mesh.node_count(); ++v) {
    const Vector3 p = mesh.nodes_mm.row(v).transpose();
    worst = std::max(worst, std::abs((p - centre).norm() - 25));
    highest = std::max(highest, p.z());
  }
  EXPECT_LT(worst, 1e-12 * 25);
  EXPECT_NEAR(highest, 10, 0.05);  // the apex, to the mesh's nearest node (within h²/2R of it)
  ASSERT_EQ(mesh.electrode_count(), 16);
  for (const auto& nodes : mesh.electrode_nodes)
    for (int v : nodes) {
      EXPECT_NEAR(mesh.nodes_mm(v, 2), 0, 1e-12);
      EXPECT_NEAR(std::hypot(mesh.nodes_mm(v, 0), mesh.nodes_mm(v, 1)), 20, 1e-12);
    }
  for (Index t = 0; t < mesh.triangle_count(); ++t) {
    const auto n = mesh.triangles.row(t);
    const Vector3 a = mesh.nodes_mm.row(n[0]), b = mesh.nodes_mm.row(n[1]), c = mesh.nodes_mm.row(n[2]);
    const Vector3 outward = (a + b + c) / 3 - centre;
    ASSERT_GT((b - a).cross(c - a).dot(outward), 0) << "triangle " << t << " faces into the sphere";
  }
}

// The mesh's area converges to the cap's, 2πR(R − √(R² − a²)) = 1570.8 mm², from below (flat
// triangles are chords of a convex surface), at second order in the mesh's edge: the observed
// order between successive meshes, measured with their mean edges (Gmsh does not halve them
// exactly), within 0.3 of 2; and the wrapped triangles stay well-shaped (the map's anisotropy is
// at most 16 %).
TEST(SphericalCap, AreaConvergesAtSecondOrderAndTrianglesStayWellShaped) {
  const double cap = surface_area_mm2(dome().shape);
  EXPECT_NEAR(cap, 2 * std::numbers::pi * 25 * 10, 1e-9);
  double previous_error = 0, previous_edge = 0;
  for (double h : {2.4, 1.2, 0.6}) {
    const Sensor sensor = dome(h);
    const MeshQuality q = measure_mesh_quality(generate_mesh(sensor, reconstruction_mesh_options(sensor)));
    const double error = (cap - q.total_area_mm2) / cap;
    std::printf("h %.1f mm: %ld triangles, area error %.2e, mean edge %.3f mm, min angle %.1f deg\n", h,
                static_cast<long>(q.triangle_count), error, q.mean_edge_mm, q.min_angle_deg);
    EXPECT_GT(error, 0);
    EXPECT_GT(q.min_angle_deg, 25);
    if (previous_error > 0) {
      const double order = std::log(previous_error / error) / std::log(previous_edge / q.mean_edge_mm);
      std::printf("  observed order %.2f\n", order);
      EXPECT_NEAR(order, 2, 0.3);
    }
    previous_error = error, previous_edge = q.mean_edge_mm;
  }
}

}  // namespace
}  // namespace emit
