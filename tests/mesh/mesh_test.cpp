// A mesh's electrode edges (mesh/mesh.hpp): the border edges whose ends are both on the electrode.
// They are counted among the electrode's own edges only (counting every edge of the mesh for each
// electrode made writing the mesh of 400 electrodes take minutes), and agree with the definition.
#include "emit/mesh/mesh.hpp"

#include <algorithm>
#include <array>
#include <vector>

#include <gtest/gtest.h>

#include "test_support.hpp"

namespace emit {
namespace {

TEST(Mesh, ElectrodeEdgesAreTheBorderEdgesOnTheElectrode) {
  const Mesh& mesh = test::dome_mesh();
  const std::vector<std::array<int, 2>> border = mesh.border_edges();
  ASSERT_EQ(mesh.electrode_count(), 16);
  for (int e = 0; e < mesh.electrode_count(); ++e) {
    const auto& nodes = mesh.electrode_nodes[static_cast<std::size_t>(e)];
    std::vector<std::array<int, 2>> expected;
    for (const auto& edge : border)
      if (std::binary_search(nodes.begin(), nodes.end(), edge[0]) &&
          std::binary_search(nodes.begin(), nodes.end(), edge[1]))
        expected.push_back(edge);
    EXPECT_EQ(mesh.electrode_edges(e), expected) << "electrode " << e;
    EXPECT_GE(expected.size(), 1u);
  }
}

}  // namespace
}  // namespace emit
