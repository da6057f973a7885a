// Offline and twin costs on the default sensor: meshing, assembly, and a frame from the forward
// model, against the naive baseline (one factorisation per grounding) in the same run.
#include <benchmark/benchmark.h>

#include "emit/fem/electrode_dofs.hpp"
#include "emit/fem/forward_model.hpp"
#include "emit/fem/sparse_cholesky.hpp"
#include "emit/fem/stiffness.hpp"
#include "emit/mesh/generate_mesh.hpp"
#include "emit/sensor/sensor_json.hpp"
#include "emit/twin/press_contact.hpp"

namespace {

using namespace emit;

const Sensor& sensor() {
  static const Sensor s = default_sensor();
  return s;
}

const Mesh& twin_mesh() {
  static const Mesh m = generate_mesh(sensor(), twin_mesh_options(sensor()));
  return m;
}

const Mesh& reconstruction_mesh() {
  static const Mesh m = generate_mesh(sensor(), reconstruction_mesh_options(sensor()));
  return m;
}

const std::vector<Press> centre_press = {{30, 30, 5, 10}};

void BM_MeshReconstruction(benchmark::State& state) {
  for ([[maybe_unused]] auto _ : state)
    benchmark::DoNotOptimize(generate_mesh(sensor(), reconstruction_mesh_options(sensor())));
  state.counters["triangles"] = static_cast<double>(reconstruction_mesh().triangle_count());
}

void BM_MeshTwin(benchmark::State& state) {
  for ([[maybe_unused]] auto _ : state) benchmark::DoNotOptimize(generate_mesh(sensor(), twin_mesh_options(sensor())));
  state.counters["triangles"] = static_cast<double>(twin_mesh().triangle_count());
}

void BM_AssembleAndAnalyse(benchmark::State& state, const Mesh& (*mesh)()) {
  for ([[maybe_unused]] auto _ : state)
    benchmark::DoNotOptimize(ForwardModel(mesh(), sensor().sheet_resistance_ohm_per_sq));
  state.counters["triangles"] = static_cast<double>(mesh().triangle_count());
}

void BM_PressContact(benchmark::State& state) {
  for ([[maybe_unused]] auto _ : state)
    benchmark::DoNotOptimize(press_contact_load(twin_mesh(), centre_press, sensor().contact));
}

// One frame: one factorisation, N solves (the regrounding trick).
void BM_Frame(benchmark::State& state, const Mesh& (*mesh)()) {
  ForwardModel model(mesh(), sensor().sheet_resistance_ohm_per_sq);
  const ContactLoad contact = press_contact_load(mesh(), centre_press, sensor().contact);
  for ([[maybe_unused]] auto _ : state) benchmark::DoNotOptimize(model.solve_frame(contact, sensor().drive_voltage_V));
  state.counters["triangles"] = static_cast<double>(mesh().triangle_count());
}

// Baseline: ground each electrode in turn and factorise that system: N factorisations a frame.
void BM_FrameNaive(benchmark::State& state, const Mesh& (*mesh)()) {
  const ElectrodeDofs dofs = number_electrode_dofs(mesh());
  const SparseMatrix K = to_dof_space(assemble_stiffness(mesh(), 1.0 / sensor().sheet_resistance_ohm_per_sq), dofs);
  const ContactLoad contact = press_contact_load(mesh(), centre_press, sensor().contact);
  const SparseMatrix C = contact_to_dof_space(mesh(), contact, dofs);
  const SparseMatrix F = K + C;
  const Vector b = sensor().drive_voltage_V * (C * Vector::Ones(dofs.dof_count));
  const int n = dofs.dof_count, N = dofs.electrode_count;
  for ([[maybe_unused]] auto _ : state) {
    for (int l = 0; l < N; ++l) {
      // The system with dof l removed: reduced index r = d − (d > l).
      std::vector<Eigen::Triplet<double, int>> grounded;
      grounded.reserve(static_cast<std::size_t>(F.nonZeros()));
      for (int col = 0; col < n; ++col)
        for (SparseMatrix::InnerIterator it(F, col); it; ++it)
          if (it.row() != l && col != l) grounded.emplace_back(it.row() - (it.row() > l), col - (col > l), it.value());
      SparseMatrix A(n - 1, n - 1);
      A.setFromTriplets(grounded.begin(), grounded.end());
      SparseCholesky cholesky;
      cholesky.factorize(A);
      Matrix rhs(n - 1, 1);
      for (int d = 0; d < n; ++d)
        if (d != l) rhs(d - (d > l), 0) = b[d];
      benchmark::DoNotOptimize(cholesky.solve(rhs));
    }
  }
  state.counters["triangles"] = static_cast<double>(mesh().triangle_count());
}

BENCHMARK(BM_MeshReconstruction)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_MeshTwin)->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_AssembleAndAnalyse, reconstruction_mesh, &reconstruction_mesh)->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_AssembleAndAnalyse, twin_mesh, &twin_mesh)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_PressContact)->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_Frame, reconstruction_mesh, &reconstruction_mesh)->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_FrameNaive, reconstruction_mesh, &reconstruction_mesh)->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_Frame, twin_mesh, &twin_mesh)->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_FrameNaive, twin_mesh, &twin_mesh)->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
