// The complete electrode model (fem/complete_electrode_model.hpp) on a disc of radius 40 mm with
// 16 electrodes: against the closed form of point electrodes on a uniform disc; reciprocity on a
// non-uniform sheet; the shunt model as its limit z → 0, approached linearly.
#include "emit/fem/complete_electrode_model.hpp"

#include <cmath>
#include <cstdio>
#include <numbers>
#include <random>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "emit/core/errors.hpp"
#include "emit/mesh/generate_mesh.hpp"
#include "emit/sensor/excitation.hpp"
#include "emit/sensor/sensor_json.hpp"
#include "test_support.hpp"

namespace emit {
namespace {

constexpr double radius_mm = 40, sheet_ohm_per_sq = 1000;

/// The disc with 16 electrodes of `width_mm` from angle 0, counter-clockwise, meshed at h.
Mesh disc_mesh(double width_mm, double element_size_mm) {
  const Sensor sensor = parse_sensor(nlohmann::json{{"shape", {{"type", "circle"}, {"radius_mm", radius_mm}}},
                                                    {"electrodes", {{"count", 16}, {"width_mm", width_mm}}}});
  MeshOptions options;
  options.element_size_mm = element_size_mm;
  options.electrode_edge_size_factor = 0.25;
  return generate_mesh(sensor, options);
}

/// A drive of 1 mA into electrode `source`, out of `sink`.
Matrix drive(int source, int sink) {
  Matrix I = Matrix::Zero(16, 1);
  I(source, 0) = 1e-3, I(sink, 0) = -1e-3;
  return I;
}

Vector2 electrode_point(int k) {
  const double a = 2 * std::numbers::pi * k / 16;
  return {radius_mm * std::cos(a), radius_mm * std::sin(a)};
}

// Point electrodes on a uniform disc, current I in at a and out at b: the potential on the border
// is (I R□/π) ln|x − b|/|x − a| + c (the boundary source's image doubles the free 1/2π). Electrodes
// of 0.5 mm on 40 mm read it to O((w/d)²) ≈ 1e-4 of the distances, and the mesh (h = 1 mm graded
// to 0.25 mm into the electrodes' ends) to O(h²/R²) ≈ 1e-3: bound 2e-3 (measured 7e-6 to 4.7e-4).
TEST(CompleteElectrodeModel, AUniformDiscReadsThePointElectrodesClosedForm) {
  const Mesh mesh = disc_mesh(0.5, 1.0);
  const CompleteElectrodeModel shunt(mesh, Vector::Constant(mesh.triangle_count(), 1 / sheet_ohm_per_sq),
                                     std::vector<double>(16, 0.0));
  const Matrix U = shunt.electrode_potentials_V(drive(0, 8));
  const Vector2 a = electrode_point(0), b = electrode_point(8);
  for (const auto& [c, d] : {std::pair{2, 6}, std::pair{1, 12}, std::pair{3, 14}, std::pair{5, 10}}) {
    const Vector2 pc = electrode_point(c), pd = electrode_point(d);
    const double expected_V = 1e-3 * sheet_ohm_per_sq / std::numbers::pi *
                              std::log((pc - b).norm() * (pd - a).norm() / ((pc - a).norm() * (pd - b).norm()));
    const double got_V = U(c, 0) - U(d, 0);
    std::printf("U%d - U%d: %.6f V, closed form %.6f V (%.2e relative)\n", c, d, got_V, expected_V,
                got_V / expected_V - 1);
    EXPECT_NEAR(got_V / expected_V, 1, 2e-3);
  }
  EXPECT_NEAR(U.sum(), 0, 1e-12);
}

// Reciprocity (the system is symmetric): driving p and reading with q equals driving q and
// reading with p, on a sheet whose conductance varies by a factor e^±1 from triangle to triangle
// and with unequal contact impedances. To rounding: 1e-10 of the readings.
TEST(CompleteElectrodeModel, ReciprocityOnANonUniformSheet) {
  const Mesh mesh = disc_mesh(3, 2.0);
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> log_factor(-1, 1), impedance(0.5, 20);
  Vector sigma(mesh.triangle_count());
  for (Index t = 0; t < sigma.size(); ++t) sigma[t] = std::exp(log_factor(rng)) / sheet_ohm_per_sq;
  std::vector<double> z(16);
  for (double& value : z) value = impedance(rng);
  const CompleteElectrodeModel cem(mesh, sigma, z);
  const Matrix p = drive(0, 5), q = drive(3, 11);
  const double pq = q.col(0).dot(cem.electrode_potentials_V(p).col(0));
  const double qp = p.col(0).dot(cem.electrode_potentials_V(q).col(0));
  EXPECT_NEAR(pq, qp, 1e-10 * std::abs(pq));
  // The nodes' potentials agree with the electrodes': a shunt electrode's nodes are its potential.
  const CompleteElectrodeModel shunt(mesh, sigma, std::vector<double>(16, 0.0));
  const Matrix u = shunt.node_potentials_V(p), U = shunt.electrode_potentials_V(p);
  for (int v : mesh.electrode_nodes[5]) EXPECT_NEAR(u(v, 0), U(5, 0), 1e-12);
}

// As z → 0 the complete electrode model tends to the shunt model, to first order in z: the
// readings' difference halves with z (ratio 2 within 10 %), and at z = 0.01 Ω·mm (0.003 Ω over a
// 3 mm electrode) it is of the order of that against the sheet's ~300 Ω between electrodes,
// 1e-5: bound 1e-5 (measured 4.4e-6, and 1.76e-5, 8.78e-6 at 0.04 and 0.02 Ω·mm).
TEST(CompleteElectrodeModel, TheShuntModelIsItsLimit) {
  const Mesh mesh = disc_mesh(3, 2.0);
  const Vector sigma = Vector::Constant(mesh.triangle_count(), 1 / sheet_ohm_per_sq);
  const Matrix I = drive(0, 8);
  const Matrix shunt = CompleteElectrodeModel(mesh, sigma, std::vector<double>(16, 0.0)).electrode_potentials_V(I);
  double previous = 0;
  for (const double z : {0.04, 0.02, 0.01}) {
    const Matrix cem = CompleteElectrodeModel(mesh, sigma, std::vector<double>(16, z)).electrode_potentials_V(I);
    const double difference = (cem - shunt).norm() / shunt.norm();
    std::printf("z = %.3f ohm mm: |U - U_shunt| / |U_shunt| = %.3e\n", z, difference);
    if (previous > 0) {
      EXPECT_NEAR(previous / difference, 2, 0.2);
    }
    previous = difference;
  }
  EXPECT_LT(previous, 1e-5);
}

// The contact impedances a sensor file may give (sensor/excitation.hpp: 1e-6 to 1e6 mm of the
// sheet, z / R□) are ones the model solves: at the low end the readings are the shunt model's to
// within 1e-6 (measured 4.7e-7: first order in z, as above), at the high end they are finite and
// reciprocal to 1e-6 (measured 1e-9) though the electrodes are as good as cut off. Beyond, the
// system loses the digits a double holds (1e-15 or 1e20 ohm mm at 5000 ohm/sq failed to factorise
// or read 0 V).
TEST(CompleteElectrodeModel, TheSensorsContactImpedanceRangeIsSolvable) {
  const Mesh mesh = disc_mesh(3, 2.0);
  const Vector sigma = Vector::Constant(mesh.triangle_count(), 1 / sheet_ohm_per_sq);
  const Matrix p = drive(0, 5), q = drive(3, 11);
  const Matrix shunt = CompleteElectrodeModel(mesh, sigma, std::vector<double>(16, 0.0)).electrode_potentials_V(p);
  const double low = Excitation::min_contact_length_mm * sheet_ohm_per_sq;
  const Matrix near_shunt = CompleteElectrodeModel(mesh, sigma, std::vector<double>(16, low)).electrode_potentials_V(p);
  std::printf("z = %g ohm mm: |U - U_shunt| / |U_shunt| = %.3e\n", low, (near_shunt - shunt).norm() / shunt.norm());
  EXPECT_LT((near_shunt - shunt).norm(), 1e-6 * shunt.norm());
  const double high = Excitation::max_contact_length_mm * sheet_ohm_per_sq;
  const CompleteElectrodeModel cut_off(mesh, sigma, std::vector<double>(16, high));
  const Matrix Up = cut_off.electrode_potentials_V(p), Uq = cut_off.electrode_potentials_V(q);
  ASSERT_TRUE(Up.allFinite() && Uq.allFinite());
  const double pq = q.col(0).dot(Up.col(0)), qp = p.col(0).dot(Uq.col(0));
  std::printf("z = %g ohm mm: reciprocity %.3e\n", high, std::abs(pq - qp) / std::abs(pq));
  EXPECT_NEAR(pq, qp, 1e-6 * std::abs(pq));
  // The driven electrodes' contacts take nearly all of the drive's voltage.
  EXPECT_GT(p.col(0).dot(Up.col(0)), 1e3 * p.col(0).dot(shunt.col(0)));
}

TEST(CompleteElectrodeModel, BadInputIsRefused) {
  const Mesh mesh = disc_mesh(3, 4.0);
  const Vector sigma = Vector::Constant(mesh.triangle_count(), 1e-3);
  EXPECT_EQ(test::error_of([&] { CompleteElectrodeModel(mesh, sigma, std::vector<double>(15, 1.0)); }),
            "EIT: 15 contact impedances for 16 electrodes");
  std::vector<double> negative(16, 1.0);
  negative[3] = -1;
  EXPECT_EQ(test::error_of([&] { CompleteElectrodeModel(mesh, sigma, negative); }),
            "EIT: electrode 3's contact impedance must be finite and >= 0");
  const CompleteElectrodeModel cem(mesh, sigma, std::vector<double>(16, 1.0));
  Matrix unbalanced = drive(0, 8);
  unbalanced(3, 0) = 1e-4;
  EXPECT_EQ(test::error_of([&] { cem.electrode_potentials_V(unbalanced); }),
            "EIT drive 0: its currents must be finite and sum to 0");
}

}  // namespace
}  // namespace emit
