// The forward model: an analytic case with its convergence rate, the all-groundings-from-one-
// factorisation trick against brute-force grounded solves, reciprocity, and the zero frame.
#include "emit/fem/forward_model.hpp"

#include <cmath>
#include <cstdio>

#include <gtest/gtest.h>
#include <Eigen/SparseCholesky>

#include "emit/core/errors.hpp"
#include "emit/fem/electrode_dofs.hpp"
#include "emit/fem/stiffness.hpp"
#include "emit/mesh/generate_mesh.hpp"
#include "emit/sensor/sensor_json.hpp"
#include "emit/twin/press_contact.hpp"
#include "test_support.hpp"
#include "tolerances.hpp"

namespace emit {
namespace {

constexpr double E = 3.3, Rs = 5000.0;

// Strip W × H, electrode 0 the bottom side (grounded), electrode 1 the top side (floating),
// uniform contact g everywhere: u'' = k²(u − E), k² = g·Rs, u(0) = 0, u'(H) = 0, so the top
// electrode reads E (1 − 1/cosh(kH)).
double strip_exact_V(double g, double H) { return E * (1.0 - 1.0 / std::cosh(std::sqrt(g * Rs) * H)); }

double strip_frame_V(int cells_per_mm, int ground, double g) {
  const double W = 4, H = 20;
  const Mesh mesh = test::strip_mesh(W, H, static_cast<int>(W * cells_per_mm), static_cast<int>(H * cells_per_mm));
  ForwardModel model(mesh, Rs);
  const ContactLoad contact = contact_load_from_elements(mesh, Vector::Constant(mesh.triangle_count(), g));
  const Frame frame = model.solve_frame(contact, E);
  return frame(ground, 1 - ground);
}

TEST(ForwardModel, StripMatchesAnalyticSolution) {
  const double g = 2e-6;  // kH = 2: a strongly curved profile
  // Ground at either end: the second goes through the 2×2 regrounding.
  for (int ground : {0, 1}) EXPECT_NEAR(strip_frame_V(4, ground, g), strip_exact_V(g, 20), 2e-3 * E);
}

TEST(ForwardModel, StripConvergesAtSecondOrder) {
  const double g = 2e-6, exact = strip_exact_V(g, 20);
  std::vector<double> errors;
  for (int cells_per_mm : {1, 2, 4}) errors.push_back(std::abs(strip_frame_V(cells_per_mm, 1, g) - exact));
  for (std::size_t i = 1; i < errors.size(); ++i) {
    const double rate = std::log2(errors[i - 1] / errors[i]);
    std::printf("strip: error %.3e V -> %.3e V, observed rate %.2f\n", errors[i - 1], errors[i], rate);
    EXPECT_GE(rate, test::min_convergence_rate)
        << "refinement " << i << ": errors " << errors[i - 1] << " → " << errors[i];
  }
}

// The same strip with a resistive driving layer (sheet resistance Rd) fed along one end: with
// d = v − u and w = Rd·u + Rs·v, d'' = k²d (k² = g(Rs + Rd)) and w'' = 0, so at the far end the
// probing sheet reads Rs/(Rs + Rd) · E (1 − 1/cosh(kH)).
TEST(ForwardModel, StripWithResistiveDrivingLayerMatchesAnalyticSolution) {
  const double W = 4, H = 20, Rd = Rs, g = 1e-6;  // kH = 2 again, and half the ideal reading
  const double exact = Rs / (Rs + Rd) * E * (1.0 - 1.0 / std::cosh(std::sqrt(g * (Rs + Rd)) * H));
  const Mesh mesh = test::strip_mesh(W, H, 16, 80);
  const ContactLoad contact = contact_load_from_elements(mesh, Vector::Constant(mesh.triangle_count(), g));
  // Fed at the grounded end; the top-fed case grounds electrode 1 through the regrounding.
  for (int ground : {0, 1}) {
    DrivingLayer layer{Vector::Constant(mesh.triangle_count(), 1.0 / Rd), {}};
    for (int node = 0; node < mesh.node_count(); ++node)
      if (std::abs(mesh.nodes_mm(node, 1) - (ground == 0 ? 0.0 : H)) < 1e-9) layer.feed_nodes.push_back(node);
    ForwardModel model(mesh, Vector::Constant(mesh.triangle_count(), 1.0 / Rs), layer);
    EXPECT_NEAR(model.solve_frame(contact, E)(ground, 1 - ground), exact, 2e-3 * E) << "ground " << ground;
  }
}

TEST(ForwardModel, NearlyIdealDrivingLayerGivesTheEquipotentialFrame) {
  const Mesh mesh = test::strip_mesh(4, 20, 8, 40);
  const ContactLoad contact = contact_load_from_elements(mesh, Vector::Constant(mesh.triangle_count(), 2e-6));
  const Vector sheet = Vector::Constant(mesh.triangle_count(), 1.0 / Rs);
  const Frame ideal = ForwardModel(mesh, sheet).solve_frame(contact, E);
  const Frame nearly = ForwardModel(mesh, sheet, bottom_fed_driving_layer(mesh, 1e-6 * Rs)).solve_frame(contact, E);
  // The driving layer's drop is first order in Rd/Rs: 1e-6 of E, far above round-off.
  EXPECT_LT((nearly - ideal).cwiseAbs().maxCoeff(), 1e-5 * E);
  EXPECT_GT(ideal.maxCoeff(), 0.1 * E);
}

TEST(ForwardModel, ZeroFrameWithoutContact) {
  ForwardModel model(test::strip_mesh(4, 4, 4, 4), Rs);
  const Frame frame = model.solve_frame(ContactLoad{}, E);
  EXPECT_EQ(frame.cwiseAbs().maxCoeff(), 0.0);
}

struct SmallSensorModel {
  Sensor sensor = default_sensor();
  Mesh mesh;
  SmallSensorModel() {
    MeshOptions options;
    options.element_size_mm = 4.0;  // small enough for dense checks
    mesh = generate_mesh(sensor, options);
  }
};

// Brute force: for each ground l, assemble F = K + C in dof space, remove dof l, solve directly
// with another solver (Eigen's simplicial LDLᵀ) — no regrounding trick.
TEST(ForwardModel, AllGroundingsAgreeWithDirectGroundedSolves) {
  SmallSensorModel s;
  const ContactLoad contact = press_contact_load(s.mesh, {{24, 33, 6, 12}, {44, 15, 4, 6}}, s.sensor.contact);
  const Frame frame = ForwardModel(s.mesh, Rs).solve_frame(contact, E);

  const ElectrodeDofs dofs = number_electrode_dofs(s.mesh);
  const SparseMatrix K = to_dof_space(assemble_stiffness(s.mesh, 1.0 / Rs), dofs);
  const Matrix F = Matrix(K) + Matrix(contact_to_dof_space(s.mesh, contact, dofs));
  const Vector b = E * (F - Matrix(K)) * Vector::Ones(F.cols());
  const int n = dofs.dof_count, N = dofs.electrode_count;
  double worst = 0;
  for (int l = 0; l < N; ++l) {
    std::vector<int> keep;
    for (int d = 0; d < n; ++d)
      if (d != l) keep.push_back(d);
    const Matrix A = F(keep, keep);
    const Vector u = A.ldlt().solve(b(keep));
    for (int m = 0; m < N; ++m) {
      const double expected = m == l ? 0.0 : u[m < l ? m : m - 1];
      worst = std::max(worst, std::abs(frame(l, m) - expected));
    }
  }
  EXPECT_LE(worst, test::solve_roundoff * E);
}

// Reciprocity: V[l][m] / E equals the fraction of a unit current injected at electrode m
// (electrode l grounded, driving layer held at 0 V) that leaks into the driving layer. The ports
// (driving layer, l) and (m, l) of a linear passive network have a symmetric transfer impedance.
TEST(ForwardModel, ReciprocityBetweenDriveAndElectrodePorts) {
  SmallSensorModel s;
  const ContactLoad contact = press_contact_load(s.mesh, {{35, 40, 5, 10}}, s.sensor.contact);
  const Frame frame = ForwardModel(s.mesh, Rs).solve_frame(contact, E);
  const ElectrodeDofs dofs = number_electrode_dofs(s.mesh);
  const SparseMatrix K = to_dof_space(assemble_stiffness(s.mesh, 1.0 / Rs), dofs);
  const SparseMatrix C = contact_to_dof_space(s.mesh, contact, dofs);
  const Matrix F = Matrix(K + C);
  const Vector leak_weights = C * Vector::Ones(C.cols());  // current into the driving layer = (C·1)ᵀ z
  for (int l : {0, 5, 11})
    for (int m : {2, 7, 14}) {
      std::vector<int> keep;
      for (int d = 0; d < dofs.dof_count; ++d)
        if (d != l) keep.push_back(d);
      Vector unit_current = Vector::Zero(dofs.dof_count - 1);
      unit_current[m < l ? m : m - 1] = 1.0;
      const Vector z = Matrix(F(keep, keep)).ldlt().solve(unit_current);
      const double leaked = leak_weights(keep).dot(z);
      EXPECT_NEAR(frame(l, m) / E, leaked, test::solve_roundoff) << "ground " << l << ", sense " << m;
    }
}

TEST(ForwardModel, GroundedElectrodeReadsZero) {
  SmallSensorModel s;
  const ContactLoad contact = press_contact_load(s.mesh, {{30, 30, 5, 10}}, s.sensor.contact);
  const Frame frame = ForwardModel(s.mesh, Rs).solve_frame(contact, E);
  EXPECT_LE(frame.diagonal().cwiseAbs().maxCoeff(), test::solve_roundoff * E);
  EXPECT_GT(frame.minCoeff(), -test::solve_roundoff);  // potentials lie in [0, E]
  EXPECT_LT(frame.maxCoeff(), E);
}

// Series resistance (contact + switch) of the grounded electrode. Independent check: no
// regrounding, one direct dense solve per grounding of the whole dof system with electrode l
// tied to ground by a conductance 1/R_l (its diagonal entry), every other electrode floating.
TEST(ForwardModel, SeriesResistanceAgreesWithDirectSolves) {
  SmallSensorModel s;
  const ContactLoad contact = press_contact_load(s.mesh, {{24, 33, 6, 12}, {44, 15, 4, 6}}, s.sensor.contact);
  ForwardModel model(s.mesh, Rs);
  std::vector<double> series(16);
  // Large against the real 0-300 ohm, so the lift (tens of mV) is far above round-off.
  for (int l = 0; l < 16; ++l) series[static_cast<std::size_t>(l)] = 2000.0 + 300.0 * l;
  model.set_series_resistance(series);
  const Frame frame = model.solve_frame(contact, E);
  const Matrix nodal = model.solve_potentials(contact, E);

  const ElectrodeDofs dofs = number_electrode_dofs(s.mesh);
  const SparseMatrix K = to_dof_space(assemble_stiffness(s.mesh, 1.0 / Rs), dofs);
  const Matrix F = Matrix(K) + Matrix(contact_to_dof_space(s.mesh, contact, dofs));
  const Vector b = E * (F - Matrix(K)) * Vector::Ones(F.cols());
  double worst = 0, largest_lift = 0;
  for (int l = 0; l < 16; ++l) {
    Matrix A = F;
    A(l, l) += 1.0 / series[static_cast<std::size_t>(l)];
    const Vector u = A.ldlt().solve(b);
    for (int m = 0; m < 16; ++m)
      if (m != l) worst = std::max(worst, std::abs(frame(l, m) - u[m]));
    // The sheet side of the grounded electrode sits at I_out·R_l above ground.
    const Index node = s.mesh.electrode_nodes[static_cast<std::size_t>(l)][0];
    worst = std::max(worst, std::abs(nodal(node, l) - u[l]));
    largest_lift = std::max(largest_lift, u[l]);
  }
  EXPECT_LE(worst, test::solve_roundoff * E);
  EXPECT_GT(largest_lift, 1e-3);                           // the check is not vacuous: the ground is lifted by > 1 mV
  EXPECT_EQ(frame.diagonal().cwiseAbs().maxCoeff(), 0.0);  // the board reads its grounded line
}

// With R = 0 the frame is today's to round-off (the 2×2 solve sees + 0.0).
TEST(ForwardModel, ZeroSeriesResistanceReproducesTheFrame) {
  SmallSensorModel s;
  const ContactLoad contact = press_contact_load(s.mesh, {{35, 40, 5, 10}}, s.sensor.contact);
  ForwardModel model(s.mesh, Rs);
  const Frame ideal = model.solve_frame(contact, E);
  model.set_series_resistance(std::vector<double>(16, 0.0));
  Frame zero = model.solve_frame(contact, E);
  zero.diagonal() = ideal.diagonal();  // set to exactly 0 with series resistances; round-off without
  EXPECT_LE((zero - ideal).cwiseAbs().maxCoeff(), test::machine_epsilon * E);
}

// Current conservation: what drains through R_l, u(e_l)/R_l, is all the current the contact
// feeds into the sheet, (C·1)ᵀE − (C u) summed, since every other electrode floats.
TEST(ForwardModel, SeriesResistanceConservesCurrent) {
  SmallSensorModel s;
  const ContactLoad contact = press_contact_load(s.mesh, {{20, 20, 5, 15}}, s.sensor.contact);
  ForwardModel model(s.mesh, Rs);
  std::vector<double> series(16, 300.0);
  model.set_series_resistance(series);
  const Matrix nodal = model.solve_potentials(contact, E);
  const ElectrodeDofs dofs = number_electrode_dofs(s.mesh);
  const SparseMatrix C = contact_to_dof_space(s.mesh, contact, dofs);
  for (int l : {0, 6, 13}) {
    Vector u(dofs.dof_count);
    for (Index v = 0; v < nodal.rows(); ++v) u[dofs.dof_of_node[v]] = nodal(v, l);
    const double fed = (C * (Vector::Constant(u.size(), E) - u)).sum();
    const double drained = u[l] / 300.0;
    EXPECT_NEAR(drained, fed, 1e-9 * fed) << "ground " << l;  // two routes to one current: round-off
    EXPECT_GT(fed, 0.0);
  }
}

// A larger series resistance lifts the grounded row, and only it (in the other groundings that
// electrode floats and draws nothing); R → ∞ leaves no ground: the sheet floats up to E.
TEST(ForwardModel, LargerSeriesResistanceLiftsItsRow) {
  SmallSensorModel s;
  const ContactLoad contact = press_contact_load(s.mesh, {{30, 25, 5, 10}}, s.sensor.contact);
  ForwardModel model(s.mesh, Rs);
  const Frame ideal = model.solve_frame(contact, E);
  for (int l : {0, 3}) {
    Frame previous = ideal;
    for (double R : {100.0, 1e3, 1e4, 1e12}) {
      std::vector<double> series(16, 0.0);
      series[static_cast<std::size_t>(l)] = R;
      model.set_series_resistance(series);
      const Frame frame = model.solve_frame(contact, E);
      for (int m = 0; m < 16; ++m) {
        if (m == l) continue;
        EXPECT_GT(frame(l, m), previous(l, m)) << "ground " << l << ", R " << R << ", sense " << m;
      }
      Frame others = frame - ideal;
      others.row(l).setZero();
      EXPECT_LE(others.cwiseAbs().maxCoeff(), test::solve_roundoff * E) << "ground " << l;
      previous = frame;
    }
    // 1e12 ohm against a contact of tens of kilo-ohm: within 1e-6 of E.
    for (int m = 0; m < 16; ++m) {
      if (m == l) continue;
      EXPECT_NEAR(previous(l, m), E, 1e-6 * E) << "ground " << l << ", sense " << m;
    }
  }
  EXPECT_THROW(model.set_series_resistance({1.0, 2.0}), InvalidInput);
  EXPECT_THROW(model.set_series_resistance(std::vector<double>(16, -1.0)), InvalidInput);
}

}  // namespace
}  // namespace emit
