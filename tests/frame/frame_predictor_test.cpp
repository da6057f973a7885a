// The model contact fitting fits: the smoothed disc's contact matrices (their total, their
// centre, their derivatives) and the Woodbury frame predictor against the sparse forward model.
#include <cmath>
#include <numbers>
#include <random>

#include <Eigen/SparseCholesky>

#include <gtest/gtest.h>

#include "emit/core/errors.hpp"
#include "emit/fem/electrode_dofs.hpp"
#include "emit/fem/forward_model.hpp"
#include "emit/fem/stiffness.hpp"
#include "emit/frame/disc_contact.hpp"
#include "emit/frame/frame_predictor.hpp"
#include "emit/mesh/generate_mesh.hpp"
#include "emit/model/green_function.hpp"
#include "emit/sensor/sensor_json.hpp"
#include "emit/sensor/surface.hpp"
#include "emit/twin/press_contact.hpp"
#include "test_support.hpp"
#include "tolerances.hpp"

namespace emit {
namespace {

const Mesh& default_mesh() {
  static const Mesh mesh = generate_mesh(default_sensor(), reconstruction_mesh_options(default_sensor()));
  return mesh;
}

/// ∫ g s dA and ∫ g s x dA of a disc load (Σ of the local matrices' entries: Σ_ij φ_i φ_j = 1).
std::pair<double, Vector2> total_and_moment(const Mesh& mesh, const DiscLoad& load) {
  double total = 0;
  Vector2 moment = Vector2::Zero();
  for (std::size_t i = 0; i < load.triangles.size(); ++i) {
    total += load.local_S[i].sum();
    moment += load.local_S[i].sum() * mesh.triangle_centroid_mm(load.triangles[i]).head<2>();
  }
  return {total, moment};
}

TEST(DiscContact, CarriesTheDiscsConductanceCentredOnIt) {
  const Mesh& mesh = default_mesh();
  const DiscContactIntegrator integrator(mesh, 0.3);
  const Disc disc{21.3, 34.7, 4.0, 2e-7};
  DiscLoad load;
  integrator.integrate(disc, load);
  const auto [total, moment] = total_and_moment(mesh, load);
  // The smoothstep is odd about the rim, so the area is π r² up to O(edge²/r²) = 0.6 %; the
  // quadrature on cut triangles (pieces 1/8 of an element) adds a fraction of that.
  const double exact = disc.conductance_S_per_mm2 * std::numbers::pi * disc.radius_mm * disc.radius_mm;
  EXPECT_NEAR(total, exact, 0.01 * exact);
  // The centre: element centroids weight the moment, exact for the inner elements, off by at
  // most an element's size times the rim's share of the total.
  const Vector2 centre = moment / total;
  EXPECT_NEAR(centre.x(), disc.x_mm, 0.05);
  EXPECT_NEAR(centre.y(), disc.y_mm, 0.05);
}

/// Each entry of the load's derivatives in x, y and r against a central difference of step
/// 1e-5 mm (the smoothstep is C¹ with second derivative ~ g·A/edge², so the difference's error is
/// far below the tolerance, a millionth of 2π r g).
void expect_derivatives_match_differences(const DiscContactIntegrator& integrator, const Disc& disc,
                                          const DiscLoad& load) {
  const double scale = 2 * std::numbers::pi * disc.radius_mm * disc.conductance_S_per_mm2;
  const double step = 1e-5;
  for (int k = 0; k < 3; ++k) {
    Disc plus = disc, minus = disc;
    double* plus_value = k == 0 ? &plus.x_mm : k == 1 ? &plus.y_mm : &plus.radius_mm;
    double* minus_value = k == 0 ? &minus.x_mm : k == 1 ? &minus.y_mm : &minus.radius_mm;
    *plus_value += step;
    *minus_value -= step;
    DiscLoad a, b;
    integrator.integrate(plus, a);
    integrator.integrate(minus, b);
    ASSERT_EQ(a.triangles, load.triangles) << "a step this small keeps the same triangles";
    ASSERT_EQ(b.triangles, load.triangles);
    double worst = 0;
    for (std::size_t i = 0; i < load.triangles.size(); ++i)
      worst =
          std::max(worst, ((a.local_S[i] - b.local_S[i]) / (2 * step) - load.d_local_S[i][k]).cwiseAbs().maxCoeff());
    EXPECT_LT(worst, 1e-6 * scale) << "parameter " << k;
  }
}

TEST(DiscContact, DerivativesMatchFiniteDifferences) {
  const Mesh& mesh = default_mesh();
  const DiscContactIntegrator integrator(mesh, 0.3);
  const Disc disc{30.4, 28.1, 3.3, 1e-7};
  DiscLoad load;
  integrator.integrate(disc, load, true);
  // The total's derivative in x and y vanishes (translation); in r it is 2π r g.
  std::array<double, 3> d_total{};
  for (const auto& d : load.d_local_S)
    for (int k = 0; k < 3; ++k) d_total[k] += d[k].sum();
  const double scale = 2 * std::numbers::pi * disc.radius_mm * disc.conductance_S_per_mm2;
  EXPECT_NEAR(d_total[2], scale, 0.02 * scale);
  expect_derivatives_match_differences(integrator, disc, load);
}

// On a sphere, the part within 3D (chord) distance r of one of its points has area π r², whatever
// the sphere's radius (Archimedes' hat-box theorem): the disc on the dome carries g π r², to the
// flat disc's smoothing and quadrature error (above) and the facets' area deficit against the
// sphere (h²/(12 R²) per element: 0.01 %). Its centre of mass is inside the sphere, below the
// surface point by r²/(4R) along the normal (0.16 mm for r = 4 mm, R = 25 mm), and on the normal.
TEST(DiscContact, OnTheDomeCarriesTheSpheresDiscOfChordRadiusR) {
  const Mesh& mesh = test::dome_mesh();
  const DiscContactIntegrator integrator(mesh, 0.3, 3, test::dome_sensor().shape);
  const Disc disc{6.2, -9.1, 4.0, 2e-7};
  DiscLoad load;
  integrator.integrate(disc, load);
  double total = 0;
  Vector3 moment = Vector3::Zero();
  for (std::size_t i = 0; i < load.triangles.size(); ++i) {
    total += load.local_S[i].sum();
    moment += load.local_S[i].sum() * mesh.triangle_centroid_mm(load.triangles[i]);
  }
  const double exact = disc.conductance_S_per_mm2 * std::numbers::pi * disc.radius_mm * disc.radius_mm;
  EXPECT_NEAR(total, exact, 0.01 * exact);
  const Vector3 surface = surface_point_mm(test::dome_sensor().shape, {disc.x_mm, disc.y_mm});
  const Vector3 normal = surface_normal(test::dome_sensor().shape, {disc.x_mm, disc.y_mm});
  const double R = test::dome_sensor().shape.sphere_radius_mm, depth = disc.radius_mm * disc.radius_mm / (4 * R);
  EXPECT_NEAR((moment / total - (surface - depth * normal)).norm(), 0, 0.05);  // as the flat disc's centre
}

// The centre's derivatives go through the surface's tangents (∂P/∂x, ∂P/∂y): against central
// differences as on the flat sheet.
TEST(DiscContact, OnTheDomeDerivativesMatchFiniteDifferences) {
  const Mesh& mesh = test::dome_mesh();
  const DiscContactIntegrator integrator(mesh, 0.3, 3, test::dome_sensor().shape);
  const Disc disc{-10.3, 7.7, 3.3, 1e-7};
  DiscLoad load;
  integrator.integrate(disc, load, true);
  expect_derivatives_match_differences(integrator, disc, load);
}

TEST(FramePredictor, AgreesWithTheSparseForwardModel) {
  const Mesh& mesh = default_mesh();
  const Sensor sensor = default_sensor();
  const DenseGreenFunction green = dense_green_function(mesh, sensor.sheet_resistance_ohm_per_sq);
  ForwardModel model(mesh, sensor.sheet_resistance_ohm_per_sq);
  FramePredictor predictor(mesh, green);
  // One press in the middle, two presses, and one touching electrode 1's border.
  for (const std::vector<Press>& presses :
       {std::vector<Press>{{30, 30, 5, 8}}, std::vector<Press>{{15, 20, 4, 5}, {45, 40, 3, 2}},
        std::vector<Press>{{22.5, 2, 3, 4}}}) {
    const ContactLoad load = press_contact_load(mesh, presses, sensor.contact);
    const Frame exact = model.solve_frame(load, sensor.drive_voltage_V);
    Frame predicted;
    predictor.predict(load.triangles, load.local_S, sensor.drive_voltage_V, predicted);
    // Two exact identities evaluated in different orders: solution round-off (cond ~1e5).
    EXPECT_LT((predicted - exact).cwiseAbs().maxCoeff(), test::solve_roundoff * exact.cwiseAbs().maxCoeff())
        << presses.size() << " presses at " << presses[0].x_mm << ", " << presses[0].y_mm;
  }
}

// A Green's function kept only on each press's block (its patch and the electrodes): each
// press's frame, read from its own block, is the full Green's function's to round-off, although
// the entries between the blocks were never computed.
TEST(FramePredictor, BlockwiseGreenFunctionGivesTheFullOnesFrames) {
  const Mesh& mesh = default_mesh();
  const Sensor sensor = default_sensor();
  const Vector conductance_S = Vector::Constant(mesh.triangle_count(), 1.0 / sensor.sheet_resistance_ohm_per_sq);
  const DenseGreenFunction full = dense_green_function(mesh, conductance_S);
  const ElectrodeDofs dofs = number_electrode_dofs(mesh);
  const std::vector<Press> presses{{30, 30, 5, 8}, {12, 47, 4, 5}, {22.5, 2, 3, 4}};
  std::vector<ContactLoad> loads;
  std::vector<std::vector<int>> blocks;
  for (const Press& press : presses) {
    loads.push_back(press_contact_load(mesh, {press}, sensor.contact));
    blocks.emplace_back();
    for (Index t : loads.back().triangles)
      for (int k = 0; k < 3; ++k) blocks.back().push_back(dofs.dof_of_node[mesh.triangles(t, k)]);
  }
  const DenseGreenFunction blockwise = blockwise_green_function(mesh, conductance_S, blocks);
  EXPECT_LT(blockwise.G0.rows(), dofs.dof_count / 4);  // only the blocks' dofs are kept
  FramePredictor from_full(mesh, full), from_blocks(mesh, blockwise);
  for (const ContactLoad& load : loads) {
    Frame exact, predicted;
    from_full.predict(load.triangles, load.local_S, sensor.drive_voltage_V, exact);
    from_blocks.predict(load.triangles, load.local_S, sensor.drive_voltage_V, predicted);
    // The same identities on G0 entries computed by different solves: solution round-off.
    EXPECT_LT((predicted - exact).cwiseAbs().maxCoeff(), test::solve_roundoff * exact.cwiseAbs().maxCoeff());
  }
}

TEST(FramePredictor, DerivativeMatchesFiniteDifferences) {
  const Mesh& mesh = default_mesh();
  const Sensor sensor = default_sensor();
  static const DenseGreenFunction green = dense_green_function(mesh, sensor.sheet_resistance_ohm_per_sq);
  FramePredictor predictor(mesh, green);
  const DiscContactIntegrator integrator(mesh, 0.3);
  const Disc disc{17.2, 41.9, 4.0, 5e-7};
  DiscLoad load;
  integrator.integrate(disc, load, true);
  Frame frame, d_frame;
  predictor.predict(load.triangles, load.local_S, sensor.drive_voltage_V, frame);
  for (int k = 0; k < 3; ++k) {
    std::vector<Eigen::Matrix3d> direction;
    for (const auto& d : load.d_local_S) direction.push_back(d[k]);
    predictor.derivative(load.triangles, direction, d_frame);
    // Central difference of the frame in x, y or r, step 1e-4 mm: its error, O(step²) times the
    // frame's third derivative, is far below 1e-4 of the derivative's size.
    const double step = 1e-4;
    Disc plus = disc, minus = disc;
    (k == 0 ? plus.x_mm : k == 1 ? plus.y_mm : plus.radius_mm) += step;
    (k == 0 ? minus.x_mm : k == 1 ? minus.y_mm : minus.radius_mm) -= step;
    DiscLoad a, b;
    integrator.integrate(plus, a);
    integrator.integrate(minus, b);
    Frame fa, fb;
    predictor.predict(a.triangles, a.local_S, sensor.drive_voltage_V, fa);
    predictor.predict(b.triangles, b.local_S, sensor.drive_voltage_V, fb);
    const Frame difference = (fa - fb) / (2 * step);
    EXPECT_LT((d_frame - difference).cwiseAbs().maxCoeff(), 1e-4 * difference.cwiseAbs().maxCoeff())
        << "parameter " << k;
    predictor.predict(load.triangles, load.local_S, sensor.drive_voltage_V, frame);  // restore the state
  }
}

/// The frame with series resistances by brute force: per grounding l, the whole sheet free, with
/// electrode l tied to ground by a conductance 1/R_l: (K + C + e_l e_lᵀ/R_l) u = E·C·1, one
/// direct sparse solve each (no regrounding, no Green's function).
Frame frame_with_series_resistance(const Mesh& mesh, double sheet_resistance, const ContactLoad& contact, double E,
                                   const std::vector<double>& ohm) {
  const ElectrodeDofs dofs = number_electrode_dofs(mesh);
  const SparseMatrix K = to_dof_space(assemble_stiffness(mesh, 1.0 / sheet_resistance), dofs);
  const SparseMatrix C = contact_to_dof_space(mesh, contact, dofs);
  const Vector drive = E * (C * Vector::Ones(dofs.dof_count));
  const int N = dofs.electrode_count;
  Frame frame = Frame::Zero(N, N);
  for (int l = 0; l < N; ++l) {
    SparseMatrix A = K + C;
    A.coeffRef(l, l) += 1.0 / ohm[static_cast<std::size_t>(l)];
    const Eigen::SimplicialLDLT<SparseMatrix> solver(A);
    const Vector u = solver.solve(drive);
    for (int m = 0; m < N; ++m)
      if (m != l) frame(l, m) = u[m];
  }
  return frame;
}

TEST(FramePredictor, SeriesResistanceAgreesWithADirectSolve) {
  const Mesh& mesh = default_mesh();
  const Sensor sensor = default_sensor();
  const DenseGreenFunction green = dense_green_function(mesh, sensor.sheet_resistance_ohm_per_sq);
  FramePredictor predictor(mesh, green);
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> resistance(1.0, 300.0);  // a realistic sheet's 0–300 Ω; > 0 for 1/R
  std::vector<double> ohm(16);
  for (double& r : ohm) r = resistance(rng);
  predictor.set_series_resistance(ohm);
  for (const std::vector<Press>& presses :
       {std::vector<Press>{{30, 30, 5, 8}}, std::vector<Press>{{15, 20, 4, 5}, {45, 40, 3, 30}}}) {
    const ContactLoad load = press_contact_load(mesh, presses, sensor.contact);
    const Frame exact =
        frame_with_series_resistance(mesh, sensor.sheet_resistance_ohm_per_sq, load, sensor.drive_voltage_V, ohm);
    Frame predicted;
    predictor.predict(load.triangles, load.local_S, sensor.drive_voltage_V, predicted);
    predicted.diagonal().setZero();  // the grounded electrode's own reading is not modelled
    // The same physics solved two ways: solution round-off (cond ~1e5, the 1/R_l terms add ~1e2).
    EXPECT_LT((predicted - exact).cwiseAbs().maxCoeff(), 100 * test::solve_roundoff * exact.cwiseAbs().maxCoeff())
        << presses.size() << " presses";
  }
  // And the resistance matters: against ideal grounds, the rows move by far more than that.
  const ContactLoad load = press_contact_load(mesh, {{30, 30, 5, 30}}, sensor.contact);
  Frame with, without;
  predictor.predict(load.triangles, load.local_S, sensor.drive_voltage_V, with);
  predictor.set_series_resistance({});
  predictor.predict(load.triangles, load.local_S, sensor.drive_voltage_V, without);
  with.diagonal().setZero();
  without.diagonal().setZero();
  EXPECT_GT((with - without).cwiseAbs().maxCoeff(), 1e-4 * without.cwiseAbs().maxCoeff());
}

TEST(FramePredictor, SeriesResistanceDerivativeMatchesFiniteDifferences) {
  const Mesh& mesh = default_mesh();
  const Sensor sensor = default_sensor();
  static const DenseGreenFunction green = dense_green_function(mesh, sensor.sheet_resistance_ohm_per_sq);
  FramePredictor predictor(mesh, green);
  std::vector<double> ohm(16);
  for (std::size_t e = 0; e < ohm.size(); ++e) ohm[e] = 20.0 * static_cast<double>(e);
  ohm[0] = 250;  // ground 0 has its own formula
  predictor.set_series_resistance(ohm);
  const DiscContactIntegrator integrator(mesh, 0.3);
  const Disc disc{17.2, 41.9, 4.0, 5e-6};  // a strong contact: its current lifts the grounds most
  DiscLoad load;
  integrator.integrate(disc, load);
  Frame frame, d_frame;
  predictor.predict(load.triangles, load.local_S, sensor.drive_voltage_V, frame);
  predictor.derivative(load.triangles, load.local_S, d_frame);  // along dC = C: d/d(log g)
  const double step = 1e-5;
  const auto scaled = [&](double factor) {
    std::vector<Eigen::Matrix3d> out;
    out.reserve(load.local_S.size());
    for (const auto& m : load.local_S) out.emplace_back(factor * m);
    return out;
  };
  Frame fa, fb;
  predictor.predict(load.triangles, scaled(std::exp(step)), sensor.drive_voltage_V, fa);
  predictor.predict(load.triangles, scaled(std::exp(-step)), sensor.drive_voltage_V, fb);
  const Frame difference = (fa - fb) / (2 * step);
  // Central difference, step 1e-5 in log g: O(step²) relative error, far below 1e-5.
  EXPECT_LT((d_frame - difference).cwiseAbs().maxCoeff(), 1e-5 * difference.cwiseAbs().maxCoeff());
}

TEST(FramePredictor, RejectsABadSeriesResistance) {
  const Mesh& mesh = default_mesh();
  static const DenseGreenFunction green = dense_green_function(mesh, 5000.0);
  FramePredictor predictor(mesh, green);
  EXPECT_THROW(predictor.set_series_resistance(std::vector<double>(15, 1.0)), InvalidInput);
  std::vector<double> negative(16, 1.0);
  negative[3] = -1;
  EXPECT_THROW(predictor.set_series_resistance(negative), InvalidInput);
}

}  // namespace
}  // namespace emit
