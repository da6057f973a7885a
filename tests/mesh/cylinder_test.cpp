// A cylinder's mesh: its chart's rectangle meshed flat and wrapped (mesh/cylinder.hpp); a sleeve's
// seam merged. Bounds below are derived for chords of a circle of radius R: for an arc s, its chord
// c = 2R sin(s/2R) satisfies 0 ≤ s − c ≤ s³/(24R²), and |R sin(a/R) − a| ≤ |a|³/(6R²).
#include "emit/mesh/cylinder.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <numbers>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "emit/fem/contact_load.hpp"
#include "emit/fem/forward_model.hpp"
#include "emit/mesh/generate_mesh.hpp"
#include "emit/sensor/sensor_json.hpp"
#include "emit/sensor/surface.hpp"
#include "test_support.hpp"

namespace emit {
namespace {

constexpr double pi = std::numbers::pi;

/// A cylinder 60 mm long with 16 electrodes of 3 mm, meshed at h.
Sensor cylinder(double radius_mm, double angle_deg, double element_size_mm) {
  return parse_sensor(
      nlohmann::json{{"shape",
                      {{"type", "cylinder"}, {"radius_mm", radius_mm}, {"length_mm", 60}, {"angle_deg", angle_deg}}},
                     {"electrodes", {{"count", 16}, {"width_mm", 3}}},
                     {"mesh", {{"element_size_mm", element_size_mm}}}});
}

Mesh mesh_of(const Sensor& sensor) { return generate_mesh(sensor, reconstruction_mesh_options(sensor)); }

Vector3 node(const Mesh& mesh, Index n) { return mesh.nodes_mm.row(n).transpose(); }

/// Bounds on the mesh's total area from the chord geometry, summed over triangles. Take a
/// triangle's vertices at angles φ_i about the axis, a_i = R (φ_i − φ̄) about their mean, u_i along
/// the axis; its chart triangle (u_i, a_i) has area A_c. Its chord triangle's projection on the
/// plane of the axis and the tangent at φ̄ is the triangle (u_i, R sin(a_i/R)), whose vertices are
/// each within ε = max|a_i|³/(6R²) of the chart's in the second coordinate; such a change alters
/// twice the area by at most U·2ε (U the u-spread; a triangle within a U × 2ε box). A triangle is
/// at least as large as its projection, so A ≥ A_c − Uε. The other two components of its normal
/// (along the radius and the axis) are at most U·a²/(2R)·2/2 and V·a²/(2R) (V the a-spread,
/// a² = max a_i²; the heights R cos(a_i/R) − R span a²/(2R)), so A ≤ √((A_c + Uε)² + (U² + V²)(a²/2R)²).
struct AreaBounds {
  double chart_mm2 = 0, lower_mm2 = 0, upper_mm2 = 0;
};
AreaBounds chord_area_bounds(const Mesh& mesh, double R) {
  AreaBounds b;
  for (Index t = 0; t < mesh.triangle_count(); ++t) {
    double phi[3], u[3], a[3];
    for (int k = 0; k < 3; ++k) {
      const Vector3 p = node(mesh, mesh.triangles(t, k));
      phi[k] = std::atan2(p.y(), p.z());
      u[k] = p.x();
    }
    for (int k = 1; k < 3; ++k) phi[k] = phi[0] + std::remainder(phi[k] - phi[0], 2 * pi);  // across a sleeve's seam
    const double mean = (phi[0] + phi[1] + phi[2]) / 3;
    for (int k = 0; k < 3; ++k) a[k] = R * (phi[k] - mean);
    const double chart = 0.5 * std::abs((u[1] - u[0]) * (a[2] - a[0]) - (a[1] - a[0]) * (u[2] - u[0]));
    const double U = *std::max_element(u, u + 3) - *std::min_element(u, u + 3);
    const double V = *std::max_element(a, a + 3) - *std::min_element(a, a + 3);
    const double a_max = std::max({std::abs(a[0]), std::abs(a[1]), std::abs(a[2])});
    const double eps = a_max * a_max * a_max / (6 * R * R), height = a_max * a_max / (2 * R);
    b.chart_mm2 += chart;
    b.lower_mm2 += chart - U * eps;
    b.upper_mm2 += std::sqrt(std::pow(chart + U * eps, 2) + (U * U + V * V) * height * height);
  }
  return b;
}

double mesh_area_mm2(const Mesh& mesh) {
  double area = 0;
  for (Index t = 0; t < mesh.triangle_count(); ++t) area += mesh.triangle_area_mm2(t);
  return area;
}

// (a) Every node on the cylinder, triangles facing out, and the area RαL within the chord bounds
// above (their gap is O(h²/R²) of the area: Uε ≤ h·(2h/3)³/(6R²) per triangle of edge h).
TEST(Cylinder, NodesOnTheCylinderAndAreaWithinTheChordBound) {
  for (const double angle : {120.0, 360.0}) {
    const double R = angle < 360 ? 20 : 15;
    const Sensor sensor = cylinder(R, angle, 1.2);
    const Mesh mesh = mesh_of(sensor);
    double off = 0;
    for (Index n = 0; n < mesh.node_count(); ++n) off = std::max(off, std::abs(node(mesh, n).tail<2>().norm() - R));
    EXPECT_LT(off, 1e-9) << angle;
    for (Index t = 0; t < mesh.triangle_count(); ++t) {
      const Vector3 a = node(mesh, mesh.triangles(t, 0)), b = node(mesh, mesh.triangles(t, 1)),
                    c = node(mesh, mesh.triangles(t, 2));
      const Vector3 outward(0, (a + b + c).y(), (a + b + c).z());
      ASSERT_GT((b - a).cross(c - a).dot(outward), 0) << "triangle " << t << " faces the axis";
    }
    const double exact = surface_area_mm2(sensor.shape), area = mesh_area_mm2(mesh);
    EXPECT_NEAR(exact, R * angle * pi / 180 * 60, 1e-9);
    const AreaBounds bounds = chord_area_bounds(mesh, R);
    std::printf("angle %.0f: %ld triangles, area %.4f of %.4f mm2 (relative %.2e), bounds [%.4f, %.4f]\n", angle,
                static_cast<long>(mesh.triangle_count()), area, exact, (exact - area) / exact, bounds.lower_mm2,
                bounds.upper_mm2);
    EXPECT_NEAR(bounds.chart_mm2, exact, 1e-9 * exact);  // the chart triangles tile the rectangle
    EXPECT_GE(area, bounds.lower_mm2);
    EXPECT_LE(area, bounds.upper_mm2);
  }
}

// (b) A sleeve's border is its two rims, closed loops at x = ±L/2 whose lengths fall short of 2πR
// by at most 2πR·s²/(24R²), s its longest edge's arc; no two nodes coincide (the seam is merged).
TEST(Cylinder, SleeveBorderIsTwoClosedRimsWithoutDuplicateNodes) {
  const double R = 15;
  const Mesh mesh = mesh_of(cylinder(R, 360, 1.2));
  const auto edges = mesh.border_edges();
  std::map<int, std::vector<int>> neighbours;
  for (const auto& e : edges) neighbours[e[0]].push_back(e[1]), neighbours[e[1]].push_back(e[0]);
  for (const auto& [n, list] : neighbours) ASSERT_EQ(list.size(), 2u) << "border node " << n << " not on one loop";
  std::map<int, bool> seen;
  int loops = 0;
  for (const auto& [start, list] : neighbours) {
    if (seen[start]) continue;
    ++loops;
    const double x = mesh.nodes_mm(start, 0);
    EXPECT_NEAR(std::abs(x), 30, 1e-9);
    double length = 0, longest = 0;
    int previous = -1, current = start;
    do {
      seen[current] = true;
      const int next = neighbours[current][0] != previous ? neighbours[current][0] : neighbours[current][1];
      EXPECT_NEAR(mesh.nodes_mm(next, 0), x, 1e-9);
      const double chord = (node(mesh, next) - node(mesh, current)).norm();
      length += chord, longest = std::max(longest, chord);
      previous = current, current = next;
    } while (current != start);
    const double arc = 2 * R * std::asin(longest / (2 * R)), round = 2 * pi * R;
    std::printf("rim at x = %+.0f: length %.6f of %.6f mm, bound %.2e\n", x, length, round,
                round * arc * arc / (24 * R * R));
    EXPECT_LE(length, round);
    EXPECT_GE(length, round * (1 - arc * arc / (24 * R * R)));
  }
  EXPECT_EQ(loops, 2);
  std::vector<int> order(static_cast<std::size_t>(mesh.node_count()));
  for (std::size_t n = 0; n < order.size(); ++n) order[n] = static_cast<int>(n);
  std::sort(order.begin(), order.end(), [&](int a, int b) { return mesh.nodes_mm(a, 0) < mesh.nodes_mm(b, 0); });
  double closest = 1e300;
  for (std::size_t i = 0; i < order.size(); ++i)
    for (std::size_t j = i + 1; j < order.size() && mesh.nodes_mm(order[j], 0) - mesh.nodes_mm(order[i], 0) < 1e-3; ++j)
      closest = std::min(closest, (node(mesh, order[j]) - node(mesh, order[i])).norm());
  EXPECT_GT(closest, 1e-6);
}

// (c) Each electrode's nodes lie on the chart's border inside its interval, both ends included:
// on a sleeve on its rim, on a patch on its rim or straight side.
TEST(Cylinder, ElectrodeNodesCoverTheirChartIntervals) {
  for (const double angle : {120.0, 360.0}) {
    const Sensor sensor = cylinder(20, angle, 1.2);
    const Mesh mesh = mesh_of(sensor);
    const Border& border = *sensor.border;
    ASSERT_EQ(mesh.electrode_count(), 16);
    for (int e = 0; e < 16; ++e) {
      const Electrode& electrode = sensor.electrodes[e];
      double first = 1e300, last = -1e300;
      for (int n : mesh.electrode_nodes[e]) {
        const Vector2 chart = surface_chart_mm(sensor.shape, node(mesh, n));
        const auto on = border.project(chart);
        EXPECT_LT(on.distance_mm, 1e-9) << "electrode " << e;
        const double from_centre = std::remainder(on.s_mm - electrode.center_s_mm, border.length_mm());
        first = std::min(first, from_centre), last = std::max(last, from_centre);
        if (angle == 360) {
          EXPECT_NEAR(std::abs(mesh.nodes_mm(n, 0)), 30, 1e-9);
        }
      }
      EXPECT_NEAR(first, -1.5, 1e-9) << "electrode " << e;
      EXPECT_NEAR(last, 1.5, 1e-9) << "electrode " << e;
    }
  }
}

/// The frame of one press (a disc of conductance in the chart) on a mesh.
Frame frame_of(const Mesh& mesh, const Mesh& chart, const Vector2& centre_mm, double radius_mm) {
  Vector g = Vector::Zero(mesh.triangle_count());
  for (Index t = 0; t < chart.triangle_count(); ++t)
    if ((chart.triangle_centroid_mm(t).head<2>() - centre_mm).norm() < radius_mm) g[t] = 2e-4;  // S/mm²
  return ForwardModel(mesh, 5000).solve_frame(contact_load_from_elements(mesh, g), 3.3);
}

struct Isometry {
  double difference_V, frame_V, distortion, longest_edge_mm;
};

/// The patch's frame against the flat chart's, both from one Gmsh mesh of the rectangle L × Rα (the
/// patch a wrapped copy), and the largest relative shrink of a squared edge length, δ.
Isometry compare_with_flat(double R, double angle_deg, double h) {
  const Sensor patch = cylinder(R, angle_deg, h);
  nlohmann::json j = sensor_to_json(patch);
  j["shape"] = {{"type", "rectangle"}, {"width_mm", 60}, {"height_mm", R * angle_deg * pi / 180}};
  j["electrodes"] = {{"count", 16}, {"width_mm", 3}};
  const Sensor flat = parse_sensor(j);
  const Mesh chart = mesh_of(flat);
  Mesh wrapped = chart;
  wrap_onto_cylinder(wrapped, patch.shape);
  double distortion = 0, longest = 0;
  for (Index t = 0; t < chart.triangle_count(); ++t)
    for (int k = 0; k < 3; ++k) {
      const int a = chart.triangles(t, k), b = chart.triangles(t, (k + 1) % 3);
      const double flat_length2 = (node(chart, a) - node(chart, b)).squaredNorm();
      longest = std::max(longest, std::sqrt(flat_length2));
      distortion = std::max(distortion, 1 - (node(wrapped, a) - node(wrapped, b)).squaredNorm() / flat_length2);
    }
  const Vector2 press(22, 0.4 * R * angle_deg * pi / 180);
  const Frame f = frame_of(chart, chart, press, 5), w = frame_of(wrapped, chart, press, 5);
  return {(w - f).cwiseAbs().maxCoeff(), f.cwiseAbs().maxCoeff(), distortion, longest};
}

// (d) The patch is an isometry of its chart, so its frames are the flat rectangle's but for the
// chords: an edge of chart length e with v-extent Δv ≤ e becomes √(e² − Δv²(1 − sinc²(Δv/2R))),
// its square short by at most δ ≤ h²/(12R²) of e² (1 − sinc² x ≤ x²/3). Each triangle's stiffness
// depends only on its edge lengths (e_i·e_j/4A); relative changes of δ in them change its energy
// and its area (the contact's mass) by a relative O(δ), and the solution of the perturbed system in
// the same ratio: we take |ΔV| ≤ 2δ·max|V| (δ for the operator, δ for the load). Being O(h²/R²),
// the difference falls 4× when R doubles on the same chart (α halved: the same Gmsh mesh, so
// exactly 4 up to the next order, (h/R)² ~ 1 %: measured 4.0006) and about 16× when h is quartered
// (other Gmsh meshes, whose constant |ΔV|/δ differs: measured 0.25 to 0.43 V over h = 2.4 … 0.3 mm,
// so the observed order between two of them may stray by log2(0.43/0.25)/2 ≈ 0.4 from 2: within 0.5).
TEST(Cylinder, PatchFramesEqualTheFlatChartsWithinTheChordDistortion) {
  const Isometry base = compare_with_flat(20, 120, 1.2);
  const Isometry wider = compare_with_flat(40, 60, 1.2);
  const Isometry finer = compare_with_flat(20, 120, 0.3);
  for (const Isometry& i : {base, wider, finer})
    std::printf("frame difference %.3e V of %.3f V, chord distortion %.3e, bound %.3e V\n", i.difference_V, i.frame_V,
                i.distortion, 2 * i.distortion * i.frame_V);
  EXPECT_GT(base.frame_V, 0.1);  // the press is felt
  for (const Isometry& i : {base, wider, finer}) {
    const double R = &i == &wider ? 40 : 20;
    EXPECT_LE(i.distortion, i.longest_edge_mm * i.longest_edge_mm / (12 * R * R));
    EXPECT_LE(i.difference_V, 2 * i.distortion * i.frame_V);
  }
  EXPECT_NEAR(base.difference_V / wider.difference_V, 4, 0.2);
  EXPECT_NEAR(std::log2(base.difference_V / finer.difference_V) / 2, 2, 0.5);
}

// A cylinder's mesh is its chart's rectangle's Gmsh mesh, wrapped: generate_mesh on the patch gives
// the nodes of wrap_onto_cylinder on the rectangle's mesh (meshing is deterministic).
TEST(Cylinder, PatchMeshIsTheRectanglesWrapped) {
  const Sensor patch = cylinder(20, 120, 1.2);
  nlohmann::json j = sensor_to_json(patch);
  j["shape"] = {{"type", "rectangle"}, {"width_mm", 60}, {"height_mm", 40 * pi / 3}};
  j["electrodes"] = {{"count", 16}, {"width_mm", 3}};
  Mesh flat = mesh_of(parse_sensor(j));
  wrap_onto_cylinder(flat, patch.shape);
  const Mesh mesh = mesh_of(patch);
  ASSERT_EQ(mesh.node_count(), flat.node_count());
  ASSERT_EQ(mesh.triangle_count(), flat.triangle_count());
  EXPECT_LT((mesh.nodes_mm - flat.nodes_mm).cwiseAbs().maxCoeff(), 1e-12);
  EXPECT_EQ(mesh.triangles, flat.triangles);
  EXPECT_EQ(mesh.electrode_nodes, flat.electrode_nodes);
}

}  // namespace
}  // namespace emit
