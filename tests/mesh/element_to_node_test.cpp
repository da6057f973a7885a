// Element values to nodes (mesh/element_to_node.hpp): each node the area-weighted mean of its
// triangles, so constants and (on a symmetric mesh) linear fields in x are kept.
#include "emit/mesh/element_to_node.hpp"

#include <gtest/gtest.h>

#include "test_support.hpp"
#include "tolerances.hpp"

namespace emit {
namespace {

TEST(ElementToNode, KeepsAConstant) {
  const Mesh mesh = test::strip_mesh(10, 4, 5, 2);
  const Vector nodes = element_to_node(mesh, Vector::Constant(mesh.triangle_count(), 0.25));
  ASSERT_EQ(nodes.size(), mesh.node_count());
  // A weighted mean of equal values: the constant, up to a few roundings.
  EXPECT_NEAR(nodes.minCoeff(), 0.25, 4 * test::machine_epsilon);
  EXPECT_NEAR(nodes.maxCoeff(), 0.25, 4 * test::machine_epsilon);
}

// Two triangles of a 2 × 1 rectangle split along (0,0)-(2,1), valued 1 and 3: the two corners on
// the diagonal touch both (equal areas, mean 2), the others one each.
TEST(ElementToNode, AreaWeightedMeanOfTheTrianglesAtANode) {
  Mesh mesh;
  mesh.nodes_mm.resize(4, 3);
  mesh.nodes_mm << 0, 0, 0, 2, 0, 0, 2, 1, 0, 0, 1, 0;
  mesh.triangles.resize(2, 3);
  mesh.triangles << 0, 1, 2, 0, 2, 3;
  Vector values(2);
  values << 1, 3;
  const Vector nodes = element_to_node(mesh, values);
  EXPECT_DOUBLE_EQ(nodes[0], 2.0);
  EXPECT_DOUBLE_EQ(nodes[1], 1.0);
  EXPECT_DOUBLE_EQ(nodes[2], 2.0);
  EXPECT_DOUBLE_EQ(nodes[3], 3.0);
}

}  // namespace
}  // namespace emit
