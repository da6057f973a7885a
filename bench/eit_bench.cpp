// The per-frame path of a current-injection skin, on the hydrogel skin's sensor
// (examples/sensors/hydrogel_hardman.json, 192 readings): the difference image's product by the
// compact NOSER operator against the dense R that pyEIT's and EIDORS's users apply, in the same
// run; and a press located with a learned press response (degree 6, as the hydrogel's 100
// calibration presses choose, over a 70 mm disc).
#include <cmath>
#include <random>

#include <benchmark/benchmark.h>

#include "emit/frame/press_locator.hpp"
#include "emit/mesh/generate_mesh.hpp"
#include "emit/model/conductivity_jacobian.hpp"
#include "emit/model/reconstruction_operator.hpp"
#include "emit/sensor/sensor_json.hpp"

namespace {

using namespace emit;

struct EitBench {
  Sensor sensor = load_sensor(EMIT_EXAMPLES_DIR "/hydrogel_hardman.json");
  Mesh mesh = generate_mesh(sensor, reconstruction_mesh_options(sensor));
  Matrix J = relative_conductivity_jacobian(mesh, sensor);
  OperatorOptions noser = [] {
    OperatorOptions o;
    o.prior = Prior::noser;
    return o;
  }();
  OperatorFamily family{J, mesh, noser.prior, noser.noser_exponent};
  CompactOperator compact = family.compact_operator_for(family.lambda2_for(noser), noser.rank_cutoff);
  Matrix dense = family.operator_for(compact.lambda2());
  /// A press's change: the Jacobian's prediction for a 10 mm disc of conductance 10 % down.
  Vector change = [this] {
    Vector d_sigma = Vector::Zero(mesh.triangle_count());
    for (Index t = 0; t < mesh.triangle_count(); ++t)
      if ((mesh.triangle_centroid_mm(t).head<2>() - Vector2(20, -30)).norm() < 10)
        d_sigma[t] = -0.1 / sensor.sheet_resistance_ohm_per_sq;
    return Vector(J * d_sigma);
  }();
};

EitBench& eit_bench() {
  static EitBench b;
  return b;
}

void BM_EitImageCompact(benchmark::State& state) {
  EitBench& b = eit_bench();
  CompactOperatorScratch scratch = b.compact.scratch();
  Vector image(b.compact.rows());
  for ([[maybe_unused]] auto _ : state) {
    b.compact.apply(b.change, image, scratch);
    benchmark::DoNotOptimize(image.data());
  }
  state.counters["triangles"] = static_cast<double>(b.mesh.triangle_count());
}

void BM_EitImageDense(benchmark::State& state) {
  EitBench& b = eit_bench();
  Vector image(b.dense.rows());
  for ([[maybe_unused]] auto _ : state) {
    image.noalias() = b.dense * b.change;
    benchmark::DoNotOptimize(image.data());
  }
}

/// A located hydrogel-sized press (degree 6, 192 readings), its frame with state.range(0) readings
/// masked (a board's dropped samples: frame/press_locator.hpp marginalises them) and the drift
/// tracked.
void BM_PressLocate(benchmark::State& state) {
  PressResponse response;
  response.degree = 6;
  response.scale_mm = 70;
  std::mt19937 random(1);
  std::normal_distribution<double> normal;
  response.coefficients = Matrix(response_basis_size(6), 192);
  for (Index i = 0; i < response.coefficients.size(); ++i) response.coefficients(i) = normal(random);
  response.precision = Matrix::Identity(192, 192);
  for (int k = 0; k < 64; ++k)
    response.region_mm.emplace_back(70 * Vector2(std::cos(k * 6.283185307 / 64), std::sin(k * 6.283185307 / 64)));
  PressLocatorOptions options;
  options.drift_rate = 0.03;
  PressLocator locator(response, options);
  Vector basis(response_basis_size(6));
  response.basis_at({20, -30}, basis);
  const Vector reference = Vector::Constant(192, 1000);
  Vector frame = (reference.array() * (0.01 * response.coefficients.transpose() * basis).array().exp()).matrix();
  for (Index m = 0; m < state.range(0); ++m) frame(7 * m + 3) = 0;
  for ([[maybe_unused]] auto _ : state) benchmark::DoNotOptimize(locator.locate(frame, reference));
  state.counters["grid_points"] = static_cast<double>(locator.grid_points());
}

}  // namespace

BENCHMARK(BM_EitImageCompact)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_EitImageDense)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_PressLocate)->Arg(0)->Arg(1)->Arg(4)->Unit(benchmark::kMicrosecond);
