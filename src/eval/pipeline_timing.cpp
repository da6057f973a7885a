#include "emit/eval/pipeline_timing.hpp"
#include "emit/model/method.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <optional>

#include <cblas.h>
#include <Eigen/Cholesky>

#include "emit/core/errors.hpp"
#include "emit/core/option_check.hpp"
#include "emit/fem/electrode_dofs.hpp"
#include "emit/fem/stiffness.hpp"
#include "emit/fem/supernodal_cholesky.hpp"
#include "emit/frame/reconstructor.hpp"
#include "emit/mesh/generate_mesh.hpp"
#include "emit/model/conductivity_jacobian.hpp"
#include "emit/model/jacobian.hpp"
#include "emit/model/operator_cache.hpp"

namespace emit {

namespace {

using Clock = std::chrono::steady_clock;

template <class Work>
double seconds(Work&& work) {
  const auto start = Clock::now();
  work();
  return std::chrono::duration<double>(Clock::now() - start).count();
}

/// Microseconds a call: the best mean of three batches of about `batch_s` each (the best, not
/// the mean: what the machine can do, not what its other tenants left).
template <class Work>
double microseconds_per_call(double batch_s, Work&& work) {
  work();  // warm-up (first-touch of scratch)
  double best = std::numeric_limits<double>::infinity();
  for (int batch = 0; batch < 3; ++batch) {
    long calls = 0;
    const auto start = Clock::now();
    double elapsed = 0;
    do {
      work();
      ++calls;
      elapsed = std::chrono::duration<double>(Clock::now() - start).count();
    } while (elapsed < batch_s);
    best = std::min(best, 1e6 * elapsed / static_cast<double>(calls));
  }
  return best;
}

/// Meshed to about `target` triangles. The count goes about as 1/h², less so on coarse meshes
/// (the electrodes' ends keep their nodes), and in steps (the frontal mesher's layers), so the
/// size is corrected by that law until it brackets the target, then bisected, until within 5 %
/// or the closest of a dozen tries. Untimed.
Mesh mesh_of_size(Sensor& sensor, const PipelineTimingOptions& options, double& mesh_s) {
  if (options.element_size_mm > 0) {
    sensor.mesh.element_size_mm = options.element_size_mm;
  } else {
    double& h = sensor.mesh.element_size_mm;
    double best_h = h, best_error = std::numeric_limits<double>::infinity();
    double too_fine = 0, too_coarse = std::numeric_limits<double>::infinity();  // the bracket on h
    for (int step = 0; step < 12 && best_error >= 0.05; ++step) {
      const Mesh trial = generate_mesh(sensor, reconstruction_mesh_options(sensor));
      const double ratio = static_cast<double>(trial.triangle_count()) / options.target_triangles;
      if (std::abs(ratio - 1) < best_error) best_error = std::abs(ratio - 1), best_h = h;
      (ratio > 1 ? too_fine : too_coarse) = h;
      h = too_fine > 0 && std::isfinite(too_coarse) ? std::sqrt(too_fine * too_coarse) : h * std::sqrt(ratio);
    }
    h = best_h;
  }
  Mesh mesh;
  mesh_s = seconds([&] { mesh = generate_mesh(sensor, reconstruction_mesh_options(sensor)); });
  return mesh;
}

/// δV of a disc of potential 1 V (radius 5 mm) at `centre`, as the Jacobian predicts it.
Vector disc_frame(const Mesh& mesh, const Matrix& J, const Vector2& centre_mm) {
  Vector dphi = Vector::Zero(mesh.triangle_count());
  for (Index t = 0; t < mesh.triangle_count(); ++t)
    if ((mesh.triangle_centroid_mm(t).head<2>() - centre_mm).norm() <= 5.0) dphi[t] = 1.0;
  return J * dphi;
}

/// The frames the per-frame figures are timed on: discs at three places of the sheet.
std::vector<Vector> three_disc_frames(const Mesh& mesh, const Matrix& J) {
  std::vector<Vector> frames;
  const Vector2 low = mesh.nodes_mm.colwise().minCoeff().head<2>().transpose();
  const Vector2 high = mesh.nodes_mm.colwise().maxCoeff().head<2>().transpose();
  for (const Vector2& fraction : {Vector2(0.3, 0.4), Vector2(0.5, 0.5), Vector2(0.75, 0.2)})
    frames.push_back(disc_frame(mesh, J, low + fraction.cwiseProduct(high - low)));
  return frames;
}

/// The case's mesh, its size checked, timed and recorded in `timing`.
Mesh timed_mesh(Sensor& sensor, const PipelineTimingOptions& options, PipelineTiming& timing) {
  if (options.target_triangles < 100 || options.target_triangles > 2'000'000)
    throw InvalidInput("bench size must be 100 to 2,000,000 triangles, got " +
                       std::to_string(options.target_triangles));
  Mesh mesh = mesh_of_size(sensor, options, timing.mesh_s);
  timing.element_size_mm = sensor.mesh.element_size_mm;
  timing.triangles = static_cast<long>(mesh.triangle_count());
  timing.electrodes = mesh.electrode_count();
  return mesh;
}

Frame as_frame(const MeasurementSet& measurements, const Vector& dV) {
  Frame frame = Frame::Zero(measurements.electrode_count, measurements.electrode_count);
  for (int i = 0; i < measurements.size(); ++i) frame.data()[measurements.frame_index[i]] = dV[i];
  return frame;
}

void time_per_frame(const ReconstructionModel& model, const Sensor& sensor, const std::vector<Vector>& frames,
                    double batch_s, PipelineTiming& timing) {
  const LinearCalibration calibration = LinearCalibration::uncalibrated(sensor);
  Reconstructor reconstructor(model, calibration);
  const int N = model.measurements.electrode_count;
  reconstructor.set_reference({Frame::Zero(N, N), 1});
  std::vector<Frame> full_frames;
  full_frames.reserve(frames.size());
  for (const Vector& dV : frames) full_frames.push_back(as_frame(model.measurements, dV));
  CompactOperatorScratch scratch = model.op.scratch();
  const auto count = frames.size();
  std::vector<Vector> images(count), pressures(count, Vector(model.op.rows()));
  std::vector<std::vector<std::uint8_t>> selections(count, std::vector<std::uint8_t>(
                                                               static_cast<std::size_t>(model.op.rows())));
  for (std::size_t i = 0; i < count; ++i) {
    model.op.apply(frames[i], images[i], scratch);
    calibration.pressure_map(images[i], 0.5 * images[i].maxCoeff(), pressures[i], selections[i]);
  }
  ContactFinder finder(model.mesh);
  Vector image(model.op.rows());
  std::size_t f = 0;
  const auto next = [&] { return f++ % count; };
  // Each stage over the same frames in turn, so the stages add up to the whole frame.
  timing.product_us = microseconds_per_call(batch_s, [&] { model.op.apply(frames[next()], image, scratch); });
  timing.pressure_us = microseconds_per_call(batch_s, [&] {
    const std::size_t i = next();
    calibration.pressure_map(images[i], 0.5 * images[i].maxCoeff(), pressures[i], selections[i]);
  });
  timing.contacts_us = microseconds_per_call(batch_s, [&] {
    const std::size_t i = next();
    finder.find(selections[i], pressures[i], images[i]);
  });
  timing.frame_us = microseconds_per_call(batch_s, [&] { reconstructor.process(full_frames[next()]); });
  volatile float sink = 0;  // keeps the read from being optimised away
  timing.operator_read_us = microseconds_per_call(batch_s, [&] {
    sink = sink + cblas_sasum(static_cast<int>(model.op.left().size()), model.op.left().data(), 1) +
           cblas_sasum(static_cast<int>(model.op.right().size()), model.op.right().data(), 1);
  });
}

double normal_equations_seconds(const Matrix& J, double lambda2) {
  return seconds([&] {
    Matrix A = J.transpose() * J;
    A.diagonal().array() += lambda2;
    const Matrix R = A.llt().solve(J.transpose());
    if (!R.allFinite()) throw SolverError("normal equations baseline: not finite");
  });
}

}  // namespace

PipelineTiming time_pipeline(const Sensor& sensor_in, const PipelineTimingOptions& options) {
  options.validate();
  Sensor sensor = sensor_in;
  PipelineTiming timing;
  const Mesh mesh = timed_mesh(sensor, options, timing);
  const MeasurementSet measurements = make_measurement_set(mesh.electrode_count());
  timing.measurements = measurements.size();

  SparseMatrix stiffness;
  const ElectrodeDofs dofs = number_electrode_dofs(mesh);
  timing.assembly_s = seconds([&] { stiffness = to_dof_space(assemble_stiffness(mesh, 1.0), dofs); });
  timing.factorisation_s = seconds([&] {  // the Jacobian's own factorisation (jacobian.cpp)
    SupernodalCholesky cholesky;
    const Index n = stiffness.rows();
    cholesky.factorize(stiffness.bottomRightCorner(n - 1, n - 1));  // electrode 0 grounded
  });

  Matrix J;
  timing.jacobian_s = seconds([&] { J = compute_jacobian(mesh, measurements); });
  const OperatorOptions paper = operator_options(Method::paper);

  const std::vector<Vector> frames = three_disc_frames(mesh, J);

  ReconstructionModel model;
  model.mesh = mesh;
  model.measurements = measurements;
  model.options = paper;
  timing.operator_s = seconds([&] { model.op = build_compact_operator(std::move(J), mesh, paper); });
  timing.rank = static_cast<int>(model.op.rank());
  if (!options.cache_dir.empty()) {
    timing.store_s = seconds([&] { store_cached_operator(options.cache_dir, "bench", model.op); });
    timing.load_s = seconds([&] {
      if (!load_cached_operator(options.cache_dir, "bench"))
        throw IoError(options.cache_dir + ": cached operator did not load back");
    });
  }
  time_per_frame(model, sensor, frames, options.seconds_per_figure, timing);
  return timing;
}

PipelineTiming time_eit_pipeline(const Sensor& sensor_in, const PipelineTimingOptions& options) {
  options.validate();
  if (!sensor_in.excitation) throw InvalidInput("bench: a current-injection case needs a sensor with an excitation");
  Sensor sensor = sensor_in;
  PipelineTiming timing;
  const Mesh mesh = timed_mesh(sensor, options, timing);
  timing.measurements = static_cast<int>(sensor.excitation->readings.size());
  Matrix J;
  timing.jacobian_s = seconds([&] { J = relative_conductivity_jacobian(mesh, sensor, &timing.factorisation_s); });

  const std::vector<Vector> frames = three_disc_frames(mesh, J);
  OperatorOptions noser;
  noser.prior = Prior::noser;
  // build_compact_operator's work, its family kept for the dense R of the baseline product below.
  std::optional<OperatorFamily> family;
  CompactOperator op;
  timing.operator_s = seconds([&] {
    family.emplace(std::move(J), mesh, noser.prior, noser.noser_exponent);
    op = family->compact_operator_for(family->lambda2_for(noser), noser.rank_cutoff);
  });
  const Matrix dense = family->operator_for(op.lambda2());
  timing.rank = static_cast<int>(op.rank());
  CompactOperatorScratch scratch = op.scratch();
  Vector image(op.rows());
  std::size_t f = 0;
  timing.product_us =
      microseconds_per_call(options.seconds_per_figure, [&] { op.apply(frames[f++ % frames.size()], image, scratch); });
  timing.frame_us = timing.product_us;
  Vector dense_image(dense.rows());
  timing.dense_product_us = microseconds_per_call(options.seconds_per_figure,
                                                  [&] { dense_image.noalias() = dense * frames[f++ % frames.size()]; });
  return timing;
}

BaselineTiming time_baselines(const Sensor& sensor_in, const PipelineTimingOptions& options, bool normal_equations,
                              bool brute_force_jacobian) {
  Sensor sensor = sensor_in;
  double mesh_s = 0;
  const Mesh mesh = mesh_of_size(sensor, options, mesh_s);
  const MeasurementSet measurements = make_measurement_set(mesh.electrode_count());
  BaselineTiming timing;
  if (normal_equations && sensor.excitation) {
    // What pyEIT's and EIDORS's difference imaging do: (JᵀJ + λ²Q)⁻¹Jᵀ, K × K.
    timing.normal_equations_s = normal_equations_seconds(relative_conductivity_jacobian(mesh, sensor), 1e-2);
  } else if (normal_equations) {
    timing.normal_equations_s =
        normal_equations_seconds(compute_jacobian(mesh, measurements), operator_options(Method::paper).lambda2);
  }
  if (brute_force_jacobian && !sensor.excitation)
    timing.brute_force_jacobian_s = seconds([&] { compute_jacobian_brute_force(mesh, measurements); });
  return timing;
}

void PipelineTimingOptions::validate() const {
  option_check::at_least("PipelineTimingOptions", "target_triangles", target_triangles, 1);
  option_check::non_negative("PipelineTimingOptions", "element_size_mm", element_size_mm);
  option_check::positive("PipelineTimingOptions", "seconds_per_figure", seconds_per_figure);
}
}  // namespace emit
