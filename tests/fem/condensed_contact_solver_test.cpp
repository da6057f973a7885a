// Condensing a contact onto a skeleton (condensed_contact_solver.hpp) solves the same system as a
// factorisation of A0 + C: checked against a dense solve on a small sheet, with contacts inside a
// cell, across cells, on the skeleton only and on the kept dofs; and the forward model's condensed
// frames against its direct ones on the default sheet, with series resistances and a press on an
// electrode.
#include "emit/fem/condensed_contact_solver.hpp"

#include <random>

#include <gtest/gtest.h>
#include <Eigen/Dense>

#include "emit/core/errors.hpp"
#include "emit/fem/forward_model.hpp"
#include "emit/fem/stiffness.hpp"
#include "emit/mesh/generate_mesh.hpp"
#include "emit/sensor/sensor_json.hpp"
#include "emit/twin/press_contact.hpp"
#include "test_support.hpp"
#include "tolerances.hpp"

namespace emit {
namespace {

using Entry = CondensedContactSolver::Entry;

/// A strip's stiffness with node 0 grounded (its row and column removed): positive definite.
struct Strip {
  Mesh mesh = test::strip_mesh(20, 20, 20, 20);
  SparseMatrix A0;
  std::vector<Vector3> position;
  Strip() {
    const SparseMatrix K = assemble_stiffness(mesh, 1.0 / 5000);
    const auto n = static_cast<int>(K.rows());
    A0 = K.bottomRightCorner(n - 1, n - 1);
    for (int v = 1; v < n; ++v) position.emplace_back(mesh.nodes_mm.row(v).transpose());
  }
};

/// The contact of a uniform conductance on triangles [first, last): entries (reduced dofs) and C·1.
void contact_on(const Mesh& mesh, Index first, Index last, double g, std::vector<Entry>& C,
                std::vector<std::pair<int, double>>& b) {
  for (Index t = first; t < last; ++t) {
    const Eigen::Matrix3d local = uniform_contact_matrix(mesh.triangle_area_mm2(t), g);
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) {
        const int r = mesh.triangles(t, i) - 1, c = mesh.triangles(t, j) - 1;
        if (r < 0) continue;
        b.emplace_back(r, local(i, j));
        if (c >= 0) C.emplace_back(r, c, local(i, j));
      }
  }
}

// The kept dofs' solution equals the dense solve of (A0 + C) X = [b, units]: both are the system's
// solution, to cond × eps (test::solve_roundoff of the largest value).
TEST(CondensedContactSolver, MatchesADenseSolve) {
  const Strip strip;
  const auto n = static_cast<int>(strip.A0.rows());
  const std::vector<int> kept = {5, 17, 200, 399, 250};  // a bottom node, a middle one, the top row's
  const std::vector<int> units = {0, 2, 3};
  for (const double cell_mm : {3.0, 7.0}) {
    CondensedContactSolver solver(strip.A0, strip.position, kept, units, cell_mm);
    ASSERT_GT(solver.cell_count(), 1);
    ASSERT_LT(solver.skeleton_size(), n / 2);
    // A press in one corner cell, one across many cells, one on a single triangle, one on a kept dof.
    for (const auto& [first, last] :
         std::vector<std::pair<Index, Index>>{{0, 6}, {300, 420}, {401, 402}, {390, 410}, {0, 0}}) {
      std::vector<Entry> C;
      std::vector<std::pair<int, double>> b;
      contact_on(strip.mesh, first, last, 2e-5, C, b);
      Matrix X;
      solver.solve(C, b, X);
      SparseMatrix Cs(n, n);
      Cs.setFromTriplets(C.begin(), C.end());
      Matrix B = Matrix::Zero(n, 1 + static_cast<Index>(units.size()));
      for (const auto& [d, v] : b) B(d, 0) += v;
      for (std::size_t k = 0; k < units.size(); ++k)
        B(kept[static_cast<std::size_t>(units[k])], static_cast<Index>(k) + 1) = 1;
      const Matrix exact = Matrix(Matrix(strip.A0) + Matrix(Cs)).llt().solve(B);
      ASSERT_EQ(X.rows(), static_cast<Index>(kept.size()));
      ASSERT_EQ(X.cols(), B.cols());
      const double scale = exact.cwiseAbs().maxCoeff();
      for (std::size_t i = 0; i < kept.size(); ++i)
        for (Index k = 0; k < B.cols(); ++k)
          EXPECT_NEAR(X(static_cast<Index>(i), k), exact(kept[i], k), test::solve_roundoff * scale)
              << "cell " << cell_mm << " mm, triangles " << first << "–" << last << ", kept " << kept[i] << ", rhs "
              << k;
    }
  }
}

TEST(CondensedContactSolver, RefusesBadInput) {
  const Strip strip;
  EXPECT_THROW(CondensedContactSolver(strip.A0, strip.position, {0}, {0}, 0.0), InvalidInput);
  EXPECT_THROW(CondensedContactSolver(strip.A0, strip.position, {-1}, {}, 3.0), InvalidInput);
  EXPECT_THROW(CondensedContactSolver(strip.A0, strip.position, {0}, {1}, 3.0), InvalidInput);
  EXPECT_THROW(CondensedContactSolver(strip.A0, {}, {0}, {0}, 3.0), InvalidInput);
  CondensedContactSolver solver(strip.A0, strip.position, {0}, {0}, 3.0);
  Matrix X;
  // Entries between nodes 0 and 399 (reduced), which A0 does not couple.
  EXPECT_THROW(solver.solve({{150, 390, 1.0}, {390, 150, 1.0}}, {}, X), InvalidInput);
}

/// The largest difference between the condensed and the direct frames, over the largest potential.
double condensed_against_direct(const Mesh& mesh, const std::vector<ContactLoad>& contacts,
                                const std::vector<double>& series_ohm) {
  ForwardModel direct(mesh, 5000), condensed(mesh, 5000);
  direct.set_series_resistance(series_ohm);
  condensed.set_series_resistance(series_ohm);
  condensed.condense_contacts();
  EXPECT_TRUE(condensed.condensed());
  double worst = 0;
  for (const ContactLoad& contact : contacts) {
    const Frame a = direct.solve_frame(contact, 3.3), b = condensed.solve_frame(contact, 3.3);
    worst = std::max(worst, (a - b).cwiseAbs().maxCoeff() / std::max(a.cwiseAbs().maxCoeff(), 1e-300));
  }
  return worst;
}

// The default sheet: presses in the middle, two at once, near electrode 0 and on an electrode's
// nodes (row 0 of the system and the drive at the ground change too); frames equal to the direct
// solve's to test::solve_roundoff of the largest potential, with and without series resistances.
TEST(CondensedContactSolver, ForwardModelFramesEqualTheDirectOnes) {
  const Sensor sensor = default_sensor();
  const Mesh mesh = generate_mesh(sensor, reconstruction_mesh_options(sensor));
  std::vector<ContactLoad> contacts;
  for (const std::vector<Press>& presses :
       std::vector<std::vector<Press>>{{{30, 30, 5, 10}}, {{12, 41, 4, 3}, {47, 20, 6, 20}}, {{31.3, 28.9, 0.7, 1}}})
    contacts.push_back(press_contact_load(mesh, presses, sensor.contact));
  for (int e : {0, 5}) {  // every triangle with a node on electrode e, and its neighbours
    const std::vector<int>& nodes = mesh.electrode_nodes[static_cast<std::size_t>(e)];
    Vector g = Vector::Zero(mesh.triangle_count());
    for (Index t = 0; t < mesh.triangle_count(); ++t)
      for (int k = 0; k < 3; ++k)
        if ((mesh.nodes_mm.row(mesh.triangles(t, k)) - mesh.nodes_mm.row(nodes[nodes.size() / 2])).norm() < 3)
          g[t] = 1e-5;
    contacts.push_back(contact_load_from_elements(mesh, g));
  }
  contacts.emplace_back();  // nothing pressed: the zero frame
  EXPECT_LE(condensed_against_direct(mesh, contacts, {}), test::solve_roundoff);
  std::vector<double> series(static_cast<std::size_t>(mesh.electrode_count()));
  for (std::size_t l = 0; l < series.size(); ++l) series[l] = 20.0 * static_cast<double>(l);
  EXPECT_LE(condensed_against_direct(mesh, contacts, series), test::solve_roundoff);
}

}  // namespace
}  // namespace emit
