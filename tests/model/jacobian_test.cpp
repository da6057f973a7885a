// The Jacobian: the fast construction (one factorisation, selected inversion) against brute-force
// Dirichlet solves, and its physical properties.
#include "emit/model/jacobian.hpp"

#include <gtest/gtest.h>

#include "emit/mesh/generate_mesh.hpp"
#include "emit/sensor/sensor_json.hpp"
#include "test_support.hpp"
#include "tolerances.hpp"

namespace emit {
namespace {

Mesh small_default_mesh() {
  MeshOptions options;
  options.element_size_mm = 7.0;  // ~150 triangles: brute force stays quick
  return generate_mesh(default_sensor(), options);
}

// docs/physics.md, "The Jacobian": the identity is exact, so the two agree to round-off (1e-10 relative).
TEST(Jacobian, FastMatchesBruteForce) {
  const Mesh mesh = small_default_mesh();
  const MeasurementSet measurements = make_measurement_set(16);
  const Matrix fast = compute_jacobian(mesh, measurements);
  const Matrix brute = compute_jacobian_brute_force(mesh, measurements);
  ASSERT_EQ(fast.rows(), 240);
  ASSERT_EQ(fast.cols(), mesh.triangle_count());
  EXPECT_LE((fast - brute).cwiseAbs().maxCoeff(), 1e-10 * brute.cwiseAbs().maxCoeff());
}

// Potentials of a sheet with sources between 0 V and 1 V lie in [0, 1] (maximum principle), and
// an element touching electrode m drives it to exactly 1 V.
TEST(Jacobian, EntriesAreBoundedByTheHeldPotential) {
  const Mesh mesh = small_default_mesh();
  const MeasurementSet measurements = make_measurement_set(16);
  const Matrix J = compute_jacobian(mesh, measurements);
  EXPECT_GE(J.minCoeff(), -test::solve_roundoff);
  EXPECT_LE(J.maxCoeff(), 1.0 + test::solve_roundoff);
  EXPECT_NEAR(J.maxCoeff(), 1.0, test::solve_roundoff);  // some element touches an electrode
}

TEST(Jacobian, LeavesOutExcludedElectrodes) {
  const Mesh mesh = small_default_mesh();
  const MeasurementSet all = make_measurement_set(16);
  const MeasurementSet without_5 = make_measurement_set(16, {5});
  EXPECT_EQ(without_5.size(), 15 * 14);
  const Matrix J_all = compute_jacobian(mesh, all);
  const Matrix J_without = compute_jacobian(mesh, without_5);
  // Same physics: each remaining row equals the corresponding full row.
  for (int r = 0; r < without_5.size(); ++r) {
    const int full_row = without_5.ground[r] * 15 + without_5.sense[r] - (without_5.sense[r] > without_5.ground[r]);
    EXPECT_LE((J_without.row(r) - J_all.row(full_row)).cwiseAbs().maxCoeff(), 1e-12);
  }
}

}  // namespace
}  // namespace emit
