#pragma once
/// \file pipeline_timing.hpp
/// How long each stage of the reconstruction takes on one sheet (`emit bench`): offline, from
/// meshing to a cached operator, and per frame, from δV to contacts; with naive baselines
/// measured in the same run where they finish in reasonable time.
#include <string>

#include "emit/sensor/sensor.hpp"

namespace emit {

struct PipelineTimingOptions {
  int target_triangles = 6000;  ///< the mesh is sized to about this many triangles
  /// Or exactly this element size [mm] (0: sized from target_triangles).
  double element_size_mm = 0;
  double seconds_per_figure = 0.3;  ///< each per-frame figure is the best of batches of this length
  std::string cache_dir;            ///< where the store/load round trip goes (a scratch folder)
  void validate() const;            ///< \throw InvalidInput naming the option (core/option_check.hpp)
};

/// Seconds for the offline stages, microseconds for the per-frame ones. A baseline not run is -1.
struct PipelineTiming {
  long triangles = 0;
  int electrodes = 0, measurements = 0, rank = 0;
  double element_size_mm = 0;
  double mesh_s = 0, assembly_s = 0, factorisation_s = 0, jacobian_s = 0, operator_s = 0;
  double store_s = 0, load_s = 0;
  double product_us = 0, pressure_us = 0, contacts_us = 0, frame_us = 0;
  /// Reading the operator's bytes once (BLAS sasum over them, at the memory's full speed): the
  /// floor under product_us, which must stream the whole operator every frame.
  double operator_read_us = 0;
  /// Current-injection only: the product by the whole operator R as a dense double matrix, #F × M
  /// (what pyEIT's and EIDORS's users apply per frame), timed like product_us; −1 otherwise.
  double dense_product_us = -1;
  double offline_s() const { return mesh_s + jacobian_s + operator_s; }  ///< mesh to operator
};

/// Times the paper method's pipeline on `sensor` meshed to about options.target_triangles.
/// Frames are the Jacobian's predictions for discs of 5 mm radius at three places, so the image
/// and its thresholded region look like a real press's. \throw InvalidInput for a bad size.
PipelineTiming time_pipeline(const Sensor& sensor, const PipelineTimingOptions& options);

/// The same for a current-injection skin (sensor.excitation), the job pyEIT's and
/// EIDORS's users run: the complete electrode model assembled and factorised on a uniform sheet
/// (factorisation_s), the relative Jacobian ∂log V/∂σ by the adjoint method (jacobian_s, which
/// includes the model), the NOSER operator at the automatic λ (operator_s); per frame, the
/// operator's product (product_us = frame_us), and the dense R's (dense_product_us). \throw InvalidInput for a sensor
/// without an excitation or a bad size.
PipelineTiming time_eit_pipeline(const Sensor& sensor, const PipelineTimingOptions& options);

/// What emit's offline path replaces, on the same mesh (options.element_size_mm as
/// time_pipeline chose it). A baseline not asked for is -1.
struct BaselineTiming {
  double normal_equations_s = -1;      ///< R = (JᵀJ + λ²I)⁻¹Jᵀ by a dense K×K Cholesky (EIDORS, pyEIT)
  double brute_force_jacobian_s = -1;  ///< J by one Dirichlet solve per element and grounding (EMIT only)
};
BaselineTiming time_baselines(const Sensor& sensor, const PipelineTimingOptions& options, bool normal_equations,
                              bool brute_force_jacobian);

}  // namespace emit
