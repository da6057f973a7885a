// The online path per frame on the default sensor: the paper method (one matrix-vector product,
// threshold, contacts; and the product alone, compact against the dense baseline) and contact
// fitting (seeded by it); and the fit's inner step, a predicted frame, by Woodbury on the
// contact's patch against the sparse forward model on the same mesh (the baseline it replaces),
// in the same run. Contact fitting on the curved sheets (the 25 mm dome, the sleeve) beside the
// flat sheet's.
#include <cmath>
#include <numbers>

#include <benchmark/benchmark.h>

#include "emit/core/threads.hpp"
#include "emit/fem/forward_model.hpp"
#include "emit/frame/contact_outline.hpp"
#include "emit/frame/frame_predictor.hpp"
#include "emit/frame/reconstructor.hpp"
#include "emit/mesh/sheet_file.hpp"
#include "emit/model/fit_model.hpp"
#include "emit/model/jacobian.hpp"
#include "emit/model/method.hpp"
#include "emit/model/reconstruction_model.hpp"
#include "emit/sensor/press.hpp"
#include "emit/sensor/press_outline.hpp"
#include "emit/sensor/sensor_json.hpp"
#include "emit/sensor/surface.hpp"
#include "emit/twin/press_contact.hpp"
#include "emit/twin/twin.hpp"

namespace {

using namespace emit;

/// The twin on another mesh than the reconstruction's (seed 3), as emit eval's.
TwinOptions held_out_twin() {
  TwinOptions o;
  o.mesh_seed = 3;
  return o;
}

struct Bench {
  Sensor sensor = default_sensor();
  ReconstructionModel model = build_reconstruction_model(sensor, operator_options(Method::paper), "");
  /// The paper method as it first stood: λ² = 10⁴ fixed, every region above the threshold a
  /// contact (no significance test, no resolution-cell floor). BM_PaperFrameBefore's baseline.
  ReconstructionModel before = [this] {
    OperatorOptions options = operator_options(Method::paper);
    options.lambda2 = 1e4;
    ReconstructionModel m = build_reconstruction_model(sensor, options, "");
    m.reading_noise_V = 0;
    return m;
  }();
  FitModel fit_model = build_fit_model(sensor);
  Twin twin{sensor, held_out_twin()};
  Frame reference = twin.frame({});
  std::vector<Frame> frames;        // single presses across the sheet
  std::vector<Frame> moving;        // a finger sliding 0.5 mm a frame (50 mm/s at 100 frames/s)
  std::vector<Frame> bars;          // a ruler's edge, 30 x 3 mm, at angles across the sheet
  std::vector<Frame> fours;         // four fingers 20 mm apart
  std::vector<Frame> fours_moving;  // four fingers 20 mm apart, each sliding 0.3 mm a frame
  Bench() {
    set_thread_count(1);
    for (double x : {12.0, 30.0, 47.0})
      for (double y : {14.0, 33.0, 50.0}) frames.push_back(twin.frame({{x, y, 5, 8}}));
    for (double angle_deg : {0.0, 35.0, 70.0, 110.0})
      bars.push_back(twin.frame({bar_press({30 - 0.05 * angle_deg, 28 + 0.04 * angle_deg}, 30, 3, angle_deg, 10)}));
    for (double shift : {0.0, 3.0, 6.0})
      fours.push_back(twin.frame(
          {{18 + shift, 18, 5, 8}, {38 + shift, 18, 5, 10}, {18, 38 + shift, 5, 12}, {38, 38 - shift, 5, 9}}));
    for (int i = 0; i < 40; ++i) moving.push_back(twin.frame({{15 + 0.5 * i, 20 + 0.35 * i, 5, 8}}));
    for (int i = 0; i < 20; ++i) {
      const double s = 0.3 * i;
      fours_moving.push_back(
          twin.frame({{18 + s, 18, 5, 8}, {38, 18 + s, 5, 10}, {18, 38 - s, 5, 12}, {38 - s, 38, 5, 9}}));
    }
  }
};

Bench& bench() {
  static Bench b;
  return b;
}

void BM_PaperFrame(benchmark::State& state) {
  Bench& b = bench();
  Reconstructor reconstructor(b.model, LinearCalibration::uncalibrated(b.sensor));
  reconstructor.set_reference({b.reference, 1});
  std::size_t f = 0;
  for ([[maybe_unused]] auto _ : state)
    benchmark::DoNotOptimize(reconstructor.process(b.frames[f++ % b.frames.size()]).size());
}

/// BM_PaperFrame's frames with state.range(0) readings lost (NaN), spread over the frame: each masked
/// reading filled by its mean given the others (frame/masked_readings.hpp), k·M + k³/3 more work.
/// /0 is BM_PaperFrame; the ratio /k : /0 is the masking's cost.
void BM_PaperFrameMasked(benchmark::State& state) {
  Bench& b = bench();
  Reconstructor reconstructor(b.model, LinearCalibration::uncalibrated(b.sensor));
  reconstructor.set_reference({b.reference, 1});
  std::vector<Frame> frames = b.frames;
  const auto lost = state.range(0);
  for (Frame& frame : frames)  // distinct readings off the diagonal: ground l, sense l + 1 (+ 7 a round)
    for (Index i = 0; i < lost; ++i) frame(i % 16, (i % 16 + 1 + 7 * (i / 16)) % 16) = std::nan("");
  std::size_t f = 0;
  for ([[maybe_unused]] auto _ : state)
    benchmark::DoNotOptimize(reconstructor.process(frames[f++ % frames.size()]).size());
  state.counters["masked"] = static_cast<double>(reconstructor.masked_readings().size());
}

/// The same frames as the paper method first reconstructed them (Bench::before).
void BM_PaperFrameBefore(benchmark::State& state) {
  Bench& b = bench();
  FrameOptions options;
  options.min_contact_cells = 0;
  Reconstructor reconstructor(b.before, LinearCalibration::uncalibrated(b.sensor), options);
  reconstructor.set_reference({b.reference, 1});
  std::size_t f = 0;
  for ([[maybe_unused]] auto _ : state)
    benchmark::DoNotOptimize(reconstructor.process(b.frames[f++ % b.frames.size()]).size());
}

/// A paper frame's outline alone (frame/contact_outline.hpp): the level line at its 50 %
/// threshold around the elements above it, the cost BM_PaperFrame includes per region.
void BM_PaperOutline(benchmark::State& state) {
  Bench& b = bench();
  RegionOutliner outliner(b.model.mesh);
  CompactOperatorScratch scratch = b.model.op.scratch();
  std::vector<Vector> images;
  std::vector<std::vector<int>> regions;
  for (const Frame& frame : b.frames) {
    Vector& image = images.emplace_back(b.model.op.rows());
    b.model.op.apply(frame_difference(b.model.measurements, frame, b.reference), image, scratch);
    std::vector<int>& region = regions.emplace_back();
    for (Index t = 0; t < image.size(); ++t)
      if (image[t] >= 0.5 * image.maxCoeff()) region.push_back(static_cast<int>(t));
  }
  Outline outline;
  std::size_t f = 0;
  for ([[maybe_unused]] auto _ : state) {
    const std::size_t k = f++ % images.size();
    outliner.outline(images[k], 0.5 * images[k].maxCoeff(), regions[k], outline);
    benchmark::DoNotOptimize(outline.size);
  }
}

/// The paper method's image alone, δφ = R·δV: the compact operator the per-frame path applies
/// (truncated, single precision, BLAS), against the full dense product it replaces (the baseline).
Vector bench_difference() {
  Bench& b = bench();
  return frame_difference(b.model.measurements, b.frames[0], b.reference);
}

void BM_PaperImageCompact(benchmark::State& state) {
  Bench& b = bench();
  const Vector dV = bench_difference();
  Vector image(b.model.op.rows());
  CompactOperatorScratch scratch = b.model.op.scratch();
  for ([[maybe_unused]] auto _ : state) {
    b.model.op.apply(dV, image, scratch);
    benchmark::DoNotOptimize(image.data());
  }
  state.counters["rank"] = static_cast<double>(b.model.op.rank());
}

void BM_PaperImageDense(benchmark::State& state) {
  Bench& b = bench();
  const Vector dV = bench_difference();
  const Matrix R = build_reconstruction_operator(compute_jacobian(b.model.mesh, b.model.measurements), b.model.mesh,
                                                 b.model.options);
  Vector image(R.rows());
  for ([[maybe_unused]] auto _ : state) {
    image.noalias() = R * dV;
    benchmark::DoNotOptimize(image.data());
  }
}

/// The curved sheets (dome, sleeve, fingertip): a sheet's models and single presses (r = 4 mm,
/// 8 N) at chart points across it (sensor/surface.hpp), for contact fitting on a curved sheet
/// beside the flat one's.
struct CurvedBench {
  Sensor sensor;
  ReconstructionModel model;
  FitModel fit_model;
  Twin twin;
  Frame reference;
  std::vector<Frame> frames;
  CurvedBench(const std::string& file, const std::vector<Vector2>& charts_mm, double press_radius_mm = 4)
      : sensor(load_sheet_sensor(file)),
        model(build_reconstruction_model(sensor, operator_options(Method::paper), "")),
        fit_model(build_fit_model(sensor)),
        twin(sensor, held_out_twin()),
        reference(twin.frame({})) {
    set_thread_count(1);
    for (const Vector2& c : charts_mm) {
      // r²/2 N: 0.16 N/mm².
      frames.push_back(
          twin.frame({press_at_chart(sensor.shape, c, press_radius_mm, press_radius_mm * press_radius_mm / 2)}));
    }
  }
};

/// The 25 mm dome: presses at least 6 mm from the rim along the surface.
CurvedBench& dome_bench() {
  static CurvedBench b(EMIT_EXAMPLES_DIR "/dome25.json", [] {
    std::vector<Vector2> charts;
    for (double x : {-10.0, 0.0, 10.0})
      for (double y : {-9.0, 1.0, 11.0}) charts.emplace_back(x, y);
    return charts;
  }());
  return b;
}

/// The sleeve (R 15 mm, L 60 mm): presses along it and round it, underneath on the seam too.
CurvedBench& sleeve_bench() {
  static CurvedBench b(EMIT_EXAMPLES_DIR "/sleeve.json", [] {
    std::vector<Vector2> charts;
    for (double u : {15.0, 30.0, 45.0})
      for (double turn : {0.0, 0.25, 0.5}) charts.emplace_back(u, turn * 2 * std::numbers::pi * 15);
    return charts;
  }());
  return b;
}

/// The CAD fingertip (a half capsule, R 9 mm): presses of a fingertip's 2.5 mm on its pad, its sides
/// and its tip.
CurvedBench& fingertip_bench() {
  static CurvedBench b(
      EMIT_EXAMPLES_DIR "/fingertip.json",
      [] {
        std::vector<Vector2> charts;
        for (double x : {-10.0, -4.0, 3.0})
          for (double y : {-4.0, 0.0, 4.0}) charts.emplace_back(x, y);
        return charts;
      }(),
      /*press_radius_mm=*/2.5);
  return b;
}

/// Contact fitting over `frames` in turn; cold (seeded from the linear image every frame) or
/// tracking (each frame started from the last one's contacts).
template <class Sheet>
void fit_frames(benchmark::State& state, Sheet& b, const std::vector<Frame>& frames, bool track, bool shapes = false) {
  const FitPrecompute fit(b.sensor, b.fit_model.mesh, b.fit_model.green, b.model.measurements);
  FrameOptions options;
  options.track_contacts = track;
  options.contact_shapes = shapes;
  Reconstructor reconstructor(b.model, fit, FitCalibration::uncalibrated(b.sensor), options);
  reconstructor.set_reference({b.reference, 1});
  std::size_t f = 0;
  double evaluations = 0, contacts = 0;
  for ([[maybe_unused]] auto _ : state) {
    const std::size_t back_and_forth = f++ % (2 * frames.size());
    const std::size_t i = back_and_forth < frames.size() ? back_and_forth : 2 * frames.size() - 1 - back_and_forth;
    contacts += static_cast<double>(reconstructor.process(frames[i]).size());
    evaluations += reconstructor.fit_result()->evaluations;
  }
  state.counters["evaluations"] = benchmark::Counter(evaluations, benchmark::Counter::kAvgIterations);
  state.counters["contacts"] = benchmark::Counter(contacts, benchmark::Counter::kAvgIterations);
}

void BM_FitFrame(benchmark::State& state) { fit_frames(state, bench(), bench().frames, false); }
/// `--method shapes`: the disc fit, then each contact refitted as an ellipse and the regions the
/// frame supports chosen (shape_refiner.hpp). Single presses, a bar, four fingers; BM_FitFrame the
/// baseline.
void BM_ShapesFrame(benchmark::State& state) { fit_frames(state, bench(), bench().frames, false, true); }
void BM_ShapesFrameBar(benchmark::State& state) { fit_frames(state, bench(), bench().bars, false, true); }
void BM_ShapesFrameFour(benchmark::State& state) { fit_frames(state, bench(), bench().fours, false, true); }
void BM_FitFrameFour(benchmark::State& state) { fit_frames(state, bench(), bench().fours, false); }
void BM_FitFrameBar(benchmark::State& state) { fit_frames(state, bench(), bench().bars, false); }
/// Streaming four fingers, each frame started from the last one's contacts (as `emit live` does).
void BM_FitFrameFourTracked(benchmark::State& state) { fit_frames(state, bench(), bench().fours_moving, true); }
void BM_ShapesFrameFourTracked(benchmark::State& state) {
  fit_frames(state, bench(), bench().fours_moving, true, true);
}
void BM_ShapesFrameMovingTracked(benchmark::State& state) { fit_frames(state, bench(), bench().moving, true, true); }
void BM_FitFrameMovingCold(benchmark::State& state) { fit_frames(state, bench(), bench().moving, false); }
void BM_FitFrameMovingTracked(benchmark::State& state) { fit_frames(state, bench(), bench().moving, true); }
void BM_FitFrameDome(benchmark::State& state) { fit_frames(state, dome_bench(), dome_bench().frames, false); }
void BM_FitFrameSleeve(benchmark::State& state) { fit_frames(state, sleeve_bench(), sleeve_bench().frames, false); }
void BM_FitFrameFingertip(benchmark::State& state) {
  fit_frames(state, fingertip_bench(), fingertip_bench().frames, false);
}

/// Reconstructors of one shared precompute fitting at once, one a thread, each with its own
/// workspace (no lock): cold fits of the single presses. items_per_second (real time) at 2 threads
/// against 1 is the scaling; the machine has two cores.
void BM_FitFrameThreads(benchmark::State& state) {
  Bench& b = bench();
  static const FitPrecompute shared(b.sensor, b.fit_model.mesh, b.fit_model.green, b.model.measurements);
  FrameOptions options;
  options.track_contacts = false;
  Reconstructor reconstructor(b.model, shared, FitCalibration::uncalibrated(b.sensor), options);
  reconstructor.set_reference({b.reference, 1});
  auto f = static_cast<std::size_t>(state.thread_index());
  for ([[maybe_unused]] auto _ : state)
    benchmark::DoNotOptimize(reconstructor.process(b.frames[f++ % b.frames.size()]).size());
  state.SetItemsProcessed(state.iterations());
}

/// One predicted frame for a disc of the fit's size (2.4 mm) on the fit's mesh.
ContactLoad fit_sized_contact() {
  Bench& b = bench();
  return press_contact_load(b.fit_model.mesh, {{21, 37, 2.4, 2}}, b.sensor.contact);
}

void BM_PredictWoodbury(benchmark::State& state) {
  Bench& b = bench();
  FramePredictor predictor(b.fit_model.mesh, b.fit_model.green);
  const ContactLoad load = fit_sized_contact();
  Frame frame;
  for ([[maybe_unused]] auto _ : state) {
    predictor.predict(load.triangles, load.local_S, b.sensor.drive_voltage_V, frame);
    benchmark::DoNotOptimize(frame.data());
  }
  state.counters["patch_triangles"] = static_cast<double>(load.triangles.size());
}

void BM_PredictSparse(benchmark::State& state) {
  Bench& b = bench();
  ForwardModel model(b.fit_model.mesh, b.sensor.sheet_resistance_ohm_per_sq);
  const ContactLoad load = fit_sized_contact();
  for ([[maybe_unused]] auto _ : state)
    benchmark::DoNotOptimize(model.solve_frame(load, b.sensor.drive_voltage_V).data());
}

BENCHMARK(BM_PaperFrame)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_PaperFrameMasked)->Arg(0)->Arg(4)->Arg(16)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_PaperFrameBefore)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_PaperOutline)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_PaperImageCompact)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_PaperImageDense)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_FitFrame)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_FitFrameFour)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_FitFrameBar)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_ShapesFrame)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_ShapesFrameBar)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_ShapesFrameFour)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_FitFrameDome)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_FitFrameSleeve)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_FitFrameFingertip)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_FitFrameMovingCold)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_FitFrameMovingTracked)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_FitFrameFourTracked)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_ShapesFrameMovingTracked)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_ShapesFrameFourTracked)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_FitFrameThreads)->Threads(1)->Threads(2)->UseRealTime()->Unit(benchmark::kMillisecond);
BENCHMARK(BM_PredictWoodbury)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_PredictSparse)->Unit(benchmark::kMicrosecond);

}  // namespace
