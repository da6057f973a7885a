// The twin's frame cost on every built-in sheet, as `emit live --source sim` asks for it: the
// figure-eight script's presses, frame after frame (the press moves and its force swings), with
// the ADC. BM_TwinFrame factorises the twin's sheet a frame (the direct solve, as emit simulate
// does); BM_TwinFrameCondensed condenses each press onto a skeleton (TwinOptions::condensed_frames,
// the live simulator's), the same frames to rounding. BM_TwinCondense is that setup, once per twin.
#include <benchmark/benchmark.h>

#include <map>
#include <memory>
#include <string>
#include <vector>

#include "emit/core/errors.hpp"
#include "emit/fem/forward_model.hpp"
#include "emit/mesh/generate_mesh.hpp"
#include "emit/mesh/sheet_file.hpp"
#include "emit/sensor/press.hpp"
#include "emit/twin/sim_source.hpp"
#include "emit/twin/twin.hpp"

namespace {

using namespace emit;

/// A sheet's twin and the presses of 200 frames of the live figure-eight (4 s at 50 frames/s),
/// built once per sheet.
struct SheetTwin {
  Sensor sensor;
  std::unique_ptr<Twin> twin, condensed;
  std::vector<std::vector<Press>> presses;
};

SheetTwin& sheet_twin(const std::string& name) {
  static std::map<std::string, std::unique_ptr<SheetTwin>> built;
  auto& slot = built[name];
  if (!slot) {
    slot = std::make_unique<SheetTwin>();
    slot->sensor = load_sheet_sensor(EMIT_EXAMPLES_DIR "/" + name + ".json");
    slot->twin = std::make_unique<Twin>(slot->sensor);
    TwinOptions condensed;
    condensed.condensed_frames = true;
    slot->condensed = std::make_unique<Twin>(slot->sensor, condensed);
    const SimSource source(slot->sensor, SimScript{}, SourceOptions{});
    for (std::uint64_t k = 15; k < 215; ++k) {
      std::vector<Press> presses = source.presses_of(k);
      // Today's script can put a press on a point the sheet's border test refuses (issue 32: the
      // circle's centre, the dome's apex): leave such frames out of the timing.
      try {
        for (const Press& p : presses) validate_press(slot->sensor, p, "press");
      } catch (const InvalidInput&) {
        continue;
      }
      slot->presses.push_back(std::move(presses));
    }
  }
  return *slot;
}

void BM_TwinFrame(benchmark::State& state, const std::string& name) {
  SheetTwin& s = sheet_twin(name);
  std::size_t k = 0;
  for ([[maybe_unused]] auto _ : state) {
    benchmark::DoNotOptimize(s.twin->frame(s.presses[k]));
    k = (k + 1) % s.presses.size();
  }
  state.counters["triangles"] = static_cast<double>(s.twin->mesh().triangle_count());
}

void BM_TwinFrameCondensed(benchmark::State& state, const std::string& name) {
  SheetTwin& s = sheet_twin(name);
  std::size_t k = 0;
  for ([[maybe_unused]] auto _ : state) {
    benchmark::DoNotOptimize(s.condensed->frame(s.presses[k]));
    k = (k + 1) % s.presses.size();
  }
  state.counters["triangles"] = static_cast<double>(s.twin->mesh().triangle_count());
}

/// The condensation's setup: one factorisation, the skeleton's solves, each cell's contact-free part.
void BM_TwinCondense(benchmark::State& state, const std::string& name) {
  const Sensor& sensor = sheet_twin(name).sensor;
  TwinOptions options;
  options.mesh = twin_mesh_options(sensor, 1);
  for ([[maybe_unused]] auto _ : state) {
    state.PauseTiming();
    ForwardModel model(generate_mesh(sensor, *options.mesh), sensor.sheet_resistance_ohm_per_sq);
    state.ResumeTiming();
    model.condense_contacts();
    state.counters["nodes"] = static_cast<double>(model.mesh().node_count());
    state.counters["skeleton"] = model.condensed_skeleton_size();
    state.counters["M_MB"] = 8e-6 * model.condensed_skeleton_size() * model.condensed_skeleton_size();
  }
}

}  // namespace

#define EMIT_TWIN_BENCH(sheet)                                                                         \
  BENCHMARK_CAPTURE(BM_TwinFrame, sheet, std::string(#sheet))->Unit(benchmark::kMillisecond);          \
  BENCHMARK_CAPTURE(BM_TwinFrameCondensed, sheet, std::string(#sheet))->Unit(benchmark::kMillisecond); \
  BENCHMARK_CAPTURE(BM_TwinCondense, sheet, std::string(#sheet))->Unit(benchmark::kMillisecond)->Iterations(1)

EMIT_TWIN_BENCH(default60);
EMIT_TWIN_BENCH(square30);
EMIT_TWIN_BENCH(circle40);
EMIT_TWIN_BENCH(hexagon);
EMIT_TWIN_BENCH(square120_32);
EMIT_TWIN_BENCH(dome25);
EMIT_TWIN_BENCH(cylinder_patch);
EMIT_TWIN_BENCH(sleeve);
EMIT_TWIN_BENCH(fingertip);
