// The EIT Jacobian ∂V/∂σ by the adjoint method (model/conductivity_jacobian.hpp) against central
// finite differences of the complete electrode model, on a non-uniform disc with contact
// impedances, opposite drives and adjacent pairs read.
#include "emit/model/conductivity_jacobian.hpp"

#include <cmath>
#include <cstdio>
#include <random>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "emit/core/errors.hpp"
#include "emit/mesh/generate_mesh.hpp"
#include "emit/sensor/sensor_json.hpp"

namespace emit {
namespace {

// V is smooth in σ_e: central differences of relative step 1e-4 are exact to O(1e-8) of a column,
// above the solves' rounding (1e-12 of V over a step of 1e-4·σ·|J|): bound 1e-6 of the column.
TEST(ConductivityJacobian, AgreesWithFiniteDifferences) {
  const Sensor sensor = parse_sensor(nlohmann::json{{"shape", {{"type", "circle"}, {"radius_mm", 40}}},
                                                    {"electrodes", {{"count", 16}, {"width_mm", 3}}}});
  MeshOptions options;
  options.element_size_mm = 5;
  const Mesh mesh = generate_mesh(sensor, options);
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> log_factor(-0.5, 0.5);
  Vector sigma(mesh.triangle_count());
  for (Index t = 0; t < sigma.size(); ++t) sigma[t] = 1e-3 * std::exp(log_factor(rng));
  const std::vector<double> z(16, 2.0);
  Matrix drives = Matrix::Zero(16, 16);
  std::vector<EitReading> readings;
  for (int d = 0; d < 16; ++d) {
    drives(d, d) = 1e-3, drives((d + 8) % 16, d) = -1e-3;  // opposite drive
    for (int m = 0; m < 16; ++m) readings.push_back({d, m, (m + 1) % 16});
  }
  const Matrix J = conductivity_jacobian(mesh, CompleteElectrodeModel(mesh, sigma, z), drives, readings);
  ASSERT_EQ(J.rows(), 256);
  ASSERT_EQ(J.cols(), mesh.triangle_count());
  const auto readings_of = [&](const Vector& s) {
    const Matrix U = CompleteElectrodeModel(mesh, s, z).electrode_potentials_V(drives);
    Vector V(static_cast<Index>(readings.size()));
    for (std::size_t i = 0; i < readings.size(); ++i)
      V[static_cast<Index>(i)] = U(readings[i].plus, readings[i].drive) - U(readings[i].minus, readings[i].drive);
    return V;
  };
  for (const Index t : {Index{0}, mesh.triangle_count() / 3, mesh.triangle_count() - 1}) {
    const double step = 1e-4 * sigma[t];
    Vector up = sigma, down = sigma;
    up[t] += step, down[t] -= step;
    const Vector column = (readings_of(up) - readings_of(down)) / (2 * step);
    const double error = (column - J.col(t)).cwiseAbs().maxCoeff() / column.cwiseAbs().maxCoeff();
    std::printf("triangle %ld: adjoint vs central differences %.2e of the column's largest\n", static_cast<long>(t),
                error);
    EXPECT_LT(error, 1e-6);
  }
}

}  // namespace
}  // namespace emit

namespace emit {
namespace {

// The shunt model's readings scale as 1/σ on a uniform sheet, so log V falls by ε when every σ_e
// rises by the factor 1 + ε: the relative Jacobian times σ is −1 on every reading (Euler's
// theorem for a function homogeneous of degree −1), to the solves' rounding.
TEST(ConductivityJacobian, RelativeJacobianIsHomogeneousOfDegreeMinusOne) {
  const Sensor sensor = parse_sensor(
      nlohmann::json{{"shape", {{"type", "circle"}, {"radius_mm", 40}}},
                     {"electrodes", {{"count", 16}, {"width_mm", 3}}},
                     {"probing_sheet_resistance_ohm_per_sq", 2000},
                     {"excitation",
                      {{"drive", "opposite"}, {"measure", "adjacent"}, {"skip_driving_electrodes", true}}}});
  MeshOptions options;
  options.element_size_mm = 5;
  const Mesh mesh = generate_mesh(sensor, options);
  double model_s = -1;
  const Matrix J = relative_conductivity_jacobian(mesh, sensor, &model_s);
  ASSERT_EQ(J.rows(), 192);
  EXPECT_GE(model_s, 0);
  const Vector row_sums = J * Vector::Constant(mesh.triangle_count(), 1.0 / 2000);
  EXPECT_LT((row_sums + Vector::Ones(192)).cwiseAbs().maxCoeff(), 1e-9);
  Sensor emit_sheet = sensor;
  emit_sheet.excitation.reset();
  EXPECT_THROW(relative_conductivity_jacobian(mesh, emit_sheet), InvalidInput);
}

}  // namespace
}  // namespace emit
