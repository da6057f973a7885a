// Renumbering a mesh for locality: the same mesh, and neighbours near each other in memory.
#include "emit/mesh/sort_for_locality.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <random>

#include <gtest/gtest.h>

#include "emit/mesh/generate_mesh.hpp"
#include "emit/sensor/sensor_json.hpp"

namespace emit {
namespace {

/// Mean index distance between consecutive triangles around each node: how far apart in memory
/// a walk over neighbours jumps.
double mean_neighbour_gap(const Mesh& mesh) {
  std::vector<std::vector<int>> around(static_cast<std::size_t>(mesh.node_count()));
  for (int t = 0; t < mesh.triangle_count(); ++t)
    for (int k = 0; k < 3; ++k) around[mesh.triangles(t, k)].push_back(t);
  double sum = 0;
  long count = 0;
  for (const std::vector<int>& triangles : around)
    for (std::size_t i = 1; i < triangles.size(); ++i, ++count) sum += triangles[i] - triangles[i - 1];
  return sum / static_cast<double>(count);
}

/// The mesh with its triangles in a random order, as a mesher might number them.
Mesh shuffled(const Mesh& mesh) {
  std::vector<int> order(static_cast<std::size_t>(mesh.triangle_count()));
  std::iota(order.begin(), order.end(), 0);
  std::shuffle(order.begin(), order.end(), std::mt19937(7));
  Mesh out = mesh;
  for (std::size_t t = 0; t < order.size(); ++t)
    out.triangles.row(static_cast<Index>(t)) = mesh.triangles.row(order[t]);
  return out;
}

/// A triangle as its three corner positions, starting from the smallest so that a rotation of
/// the same triangle compares equal (orientation is kept: no reflection).
std::array<double, 6> corners(const Mesh& mesh, Index t) {
  std::array<std::array<double, 2>, 3> p{};
  for (int k = 0; k < 3; ++k) p[k] = {mesh.nodes_mm(mesh.triangles(t, k), 0), mesh.nodes_mm(mesh.triangles(t, k), 1)};
  std::rotate(p.begin(), std::min_element(p.begin(), p.end()), p.end());
  return {p[0][0], p[0][1], p[1][0], p[1][1], p[2][0], p[2][1]};
}

std::vector<std::array<double, 6>> all_corners(const Mesh& mesh) {
  std::vector<std::array<double, 6>> all;
  for (Index t = 0; t < mesh.triangle_count(); ++t) all.push_back(corners(mesh, t));
  std::sort(all.begin(), all.end());
  return all;
}

TEST(SortForLocality, KeepsEveryTriangleWithItsOrientationAndEveryElectrode) {
  const Sensor sensor = default_sensor();
  const Mesh mesh = shuffled(generate_mesh(sensor, reconstruction_mesh_options(sensor)));
  const Mesh sorted = sort_for_locality(mesh);
  ASSERT_EQ(sorted.node_count(), mesh.node_count());
  ASSERT_EQ(sorted.triangle_count(), mesh.triangle_count());
  EXPECT_EQ(all_corners(sorted), all_corners(mesh));  // exact: positions are copied, not computed
  ASSERT_EQ(sorted.electrode_count(), mesh.electrode_count());
  for (int e = 0; e < mesh.electrode_count(); ++e) {
    ASSERT_TRUE(std::is_sorted(sorted.electrode_nodes[e].begin(), sorted.electrode_nodes[e].end()));
    std::vector<std::array<double, 2>> before, after;
    for (int v : mesh.electrode_nodes[e]) before.push_back({mesh.nodes_mm(v, 0), mesh.nodes_mm(v, 1)});
    for (int v : sorted.electrode_nodes[e]) after.push_back({sorted.nodes_mm(v, 0), sorted.nodes_mm(v, 1)});
    std::sort(before.begin(), before.end());
    std::sort(after.begin(), after.end());
    EXPECT_EQ(after, before) << "electrode " << e;
  }
}

// Along a Z-order curve, triangles around a node sit O(√#F) indices apart on a quasi-uniform mesh
// (a curve's neighbours in space are at most a few of its quadrant blocks apart); in a random
// order they sit about #F/3 apart. 2√#F is the bound: measured ~0.6√#F on 12k and 43k triangles.
TEST(SortForLocality, PutsNeighboursNearEachOtherInMemory) {
  const Sensor sensor = default_sensor();
  const Mesh mesh = shuffled(generate_mesh(sensor, reconstruction_mesh_options(sensor)));
  const double sqrt_F = std::sqrt(static_cast<double>(mesh.triangle_count()));
  EXPECT_GT(mean_neighbour_gap(mesh), 10 * sqrt_F);  // the shuffled mesh really is scattered
  EXPECT_LT(mean_neighbour_gap(sort_for_locality(mesh)), 2 * sqrt_F);
}

TEST(SortForLocality, GeneratedMeshesComeOutSorted) {
  const Sensor sensor = default_sensor();
  const Mesh mesh = generate_mesh(sensor, reconstruction_mesh_options(sensor));
  EXPECT_LT(mean_neighbour_gap(mesh), 2 * std::sqrt(static_cast<double>(mesh.triangle_count())));
}

}  // namespace
}  // namespace emit
