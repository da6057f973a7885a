// A field calibration's cost on the default sensor: emit calibrate's sensor fit of 40 presses of
// known place on a realistic sheet (its Green's functions dominate), and one Green's function on
// the presses' blocks against the same columns by sparse solves (the baseline) in the same run.
#include <benchmark/benchmark.h>

#include "emit/eval/evaluation.hpp"
#include "emit/fem/electrode_dofs.hpp"
#include "emit/frame/contact_fitter.hpp"
#include "emit/frame/disc_contact.hpp"
#include "emit/model/fit_model.hpp"
#include "emit/model/green_function.hpp"
#include "emit/pipeline/press_calibration.hpp"
#include "emit/sensor/sensor_json.hpp"
#include "emit/twin/press_scripts.hpp"
#include "emit/twin/realistic_sheet.hpp"

namespace {

using namespace emit;

struct CalibrationRound {
  Sensor sensor = default_sensor();
  SimulatedRun run;
  CalibrationRound() {
    RealisticSheetOptions sheet_options;
    sheet_options.seed = 3;
    const RealisticSheet sheet = make_realistic_sheet(sensor, sheet_options);
    Twin twin(sheet.twin_sensor, sheet.twin_options);
    PressStyle style;  // the realistic evaluation's calibration presses
    style.min_force_N = 2, style.max_force_N = 39, style.seed = 4;
    run = simulate_run(twin, random_script(sensor, 40, style));
  }
};

const CalibrationRound& round() {
  static const CalibrationRound r;
  return r;
}

void BM_CalibrateSheet40Presses(benchmark::State& state) {
  const CalibrationRound& r = round();
  PressCalibrationOptions options;  // emit calibrate's defaults
  for ([[maybe_unused]] auto _ : state)
    benchmark::DoNotOptimize(calibrate_from_presses(r.sensor, options, r.run.reference, r.run.frames, r.run.presses));
}

/// The dofs of each press's disc patch on the fit mesh: what the calibration's Green's functions hold.
std::vector<std::vector<int>> press_blocks(const Mesh& mesh) {
  const CalibrationRound& r = round();
  const ElectrodeDofs dofs = number_electrode_dofs(mesh);
  const FitOptions fit = resolved_fit_options({}, r.sensor, mesh);
  const DiscContactIntegrator integrator(mesh, fit.edge_mm, 3, r.sensor.shape);
  std::vector<std::vector<int>> blocks;
  for (const std::vector<Press>& presses : r.run.presses) {
    DiscLoad load;
    integrator.integrate({presses[0].x_mm, presses[0].y_mm, fit.prior_radius_mm, 1.0}, load);
    blocks.emplace_back();
    for (Index t : load.triangles)
      for (int k = 0; k < 3; ++k) blocks.back().push_back(dofs.dof_of_node[mesh.triangles(t, k)]);
  }
  return blocks;
}

void BM_GreenFunction40Presses(benchmark::State& state, bool blockwise) {
  const Mesh mesh = fit_mesh(round().sensor);
  const Vector conductance_S =
      Vector::Constant(mesh.triangle_count(), 1.0 / round().sensor.sheet_resistance_ohm_per_sq);
  const std::vector<std::vector<int>> blocks = press_blocks(mesh);
  std::vector<int> columns;
  for (int e = 0; e < number_electrode_dofs(mesh).electrode_count; ++e) columns.push_back(e);
  for (const std::vector<int>& block : blocks) columns.insert(columns.end(), block.begin(), block.end());
  for ([[maybe_unused]] auto _ : state)
    benchmark::DoNotOptimize(blockwise ? blockwise_green_function(mesh, conductance_S, blocks)
                                       : dense_green_function(mesh, conductance_S, columns));
  state.counters["dofs"] = static_cast<double>(number_electrode_dofs(mesh).dof_count);
}

}  // namespace

BENCHMARK(BM_CalibrateSheet40Presses)->Unit(benchmark::kSecond)->Iterations(1);
BENCHMARK_CAPTURE(BM_GreenFunction40Presses, columns_by_solves, false)->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_GreenFunction40Presses, blocks_by_tree_paths, true)->Unit(benchmark::kMillisecond);
