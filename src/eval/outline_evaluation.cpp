#include "emit/eval/outline_evaluation.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <limits>
#include <optional>

#include "emit/core/errors.hpp"
#include "emit/eval/evaluation.hpp"
#include "emit/pipeline/pipeline.hpp"
#include "emit/pipeline/press_calibration.hpp"
#include "emit/sensor/surface.hpp"
#include "emit/twin/press_scripts.hpp"
#include "emit/twin/twin.hpp"

namespace emit {

OutlineEvalOptions quick_outline_options() {
  OutlineEvalOptions options;
  options.presses_per_family = 1;
  options.calibration_presses = 16;    // twice the sensor fit's least: a smoke test's calibration
  options.calibration_iterations = 2;  // as quick_realistic_counts: the misfit's bulk goes in two
  return options;
}

void OutlineEvalOptions::validate() const {
  const auto at_least = [](int value, int least, const char* name) {
    if (value < least)
      throw InvalidInput(std::string("outline evaluation: ") + name + " must be " + std::to_string(least) +
                         " or more, got " + std::to_string(value));
  };
  at_least(reference_frames, 1, "reference_frames");
  at_least(calibration_presses, 8, "calibration_presses");  // calibrate_sensor's least
  at_least(presses_per_family, 1, "presses_per_family");
  at_least(calibration_iterations, 0, "calibration_iterations");
  if (methods.empty()) throw InvalidInput("outline evaluation: no method to evaluate");
  if (indenters && indenter_radii_mm.empty()) throw InvalidInput("outline evaluation: no indenter radius");
  for (const double r : indenter_radii_mm)
    if (!(r > 0 && r <= 12))
      throw InvalidInput("outline evaluation: an indenter's radius must be in (0, 12] mm, got " + std::to_string(r));
}

OutlineFamilyScore summarize_outline_scores(const std::string& family, const std::vector<OutlineScore>& scores) {
  OutlineFamilyScore s;
  s.family = family;
  s.frames = static_cast<int>(scores.size());
  int centroids = 0, orientations = 0, area_sigmas = 0, force_sigmas = 0;
  double orientation_sum = 0;
  for (const OutlineScore& f : scores) {
    s.area_ratio += f.true_area_mm2 > 0 ? f.area_mm2 / f.true_area_mm2 : 0;
    area_sigmas += f.area_std_mm2 > 0;
    force_sigmas += f.force_std_N > 0;
    s.area_within_1sigma += within_sigmas(f.area_mm2, f.area_std_mm2, f.true_area_mm2, 1);
    s.area_within_2sigma += within_sigmas(f.area_mm2, f.area_std_mm2, f.true_area_mm2, 2);
    s.force_within_1sigma += within_sigmas(f.force_N, f.force_std_N, f.true_force_N, 1);
    s.force_within_2sigma += within_sigmas(f.force_N, f.force_std_N, f.true_force_N, 2);
    s.dice += f.dice;
    const double ratio = f.true_force_N > 0 ? f.force_N / f.true_force_N : 0;
    s.force_ratio += ratio;
    s.force_error += std::abs(ratio - 1);
    if (std::isfinite(f.centroid_error_mm)) {
      s.centroid_mm += f.centroid_error_mm;
      ++centroids;
    } else {
      ++s.frames_without_region;
    }
    if (std::isfinite(f.orientation_error_deg)) {
      orientation_sum += f.orientation_error_deg;
      ++orientations;
    }
    s.regions += f.regions;
    s.right_count += f.regions == f.presses ? 1 : 0;
  }
  if (s.frames > 0) {
    const double n = s.frames;
    s.dice /= n, s.force_ratio /= n, s.force_error /= n, s.regions /= n, s.right_count /= n, s.area_ratio /= n;
    s.area_within_1sigma /= n, s.area_within_2sigma /= n, s.force_within_1sigma /= n, s.force_within_2sigma /= n;
  }
  constexpr double none = std::numeric_limits<double>::quiet_NaN();
  if (area_sigmas == 0) s.area_within_1sigma = s.area_within_2sigma = none;
  if (force_sigmas == 0) s.force_within_1sigma = s.force_within_2sigma = none;
  s.centroid_mm = centroids > 0 ? s.centroid_mm / centroids : std::numeric_limits<double>::quiet_NaN();
  s.orientation_deg = orientations > 0 ? orientation_sum / orientations : std::numeric_limits<double>::quiet_NaN();
  return s;
}

namespace {

using Clock = std::chrono::steady_clock;

/// The calibration presses of `emit eval --realistic`'s round on the 60 mm sheet: a 5 mm flat
/// indenter, 2–39 N (0.025–0.5 N/mm², the paper's range), at least its radius from the border.
PressSequence calibration_script(const Sensor& sensor, int presses, std::uint64_t seed) {
  PressStyle style;
  style.radius_mm = 5;
  style.min_force_N = 2, style.max_force_N = 39;
  style.margin_mm = 5;
  style.seed = seed;
  return random_script(sensor, presses, style);
}

std::vector<Frame> simulate(Twin& twin, const PressSequence& presses, const std::string& what,
                            const Progress& progress) {
  std::vector<Frame> frames;
  frames.reserve(presses.size());
  for (const std::vector<Press>& p : presses) {
    frames.push_back(twin.frame(p));
    progress.step("simulating " + what, static_cast<long>(frames.size()), static_cast<long>(presses.size()));
  }
  return frames;
}

}  // namespace

OutlineEvaluation evaluate_outlines(const EvalCase& eval_case, const OutlineEvalOptions& options,
                                    const Progress& progress) {
  options.validate();
  const Sensor& sensor = eval_case.sensor;
  if (is_curved(sensor.shape)) throw InvalidInput("outline evaluation: the sheet must be flat");
  // The outlines first: a sheet without room for them is refused before any solve.
  // Each family's name, frames' presses and, in the indenter sweep, its radius (to declare).
  std::vector<std::string> names;
  std::vector<PressSequence> outlines;
  std::vector<double> radii_mm;
  if (options.indenters) {
    for (std::size_t k = 0; k < options.indenter_radii_mm.size(); ++k) {
      PressStyle style;  // as the outlines: 4–16 N, every point of the disc 3 mm inside the border
      style.radius_mm = options.indenter_radii_mm[k];
      style.min_force_N = 4, style.max_force_N = 16;
      style.margin_mm = style.radius_mm + 3;
      style.seed = options.seed + 101 + k;
      char name[32];
      std::snprintf(name, sizeof name, "disc r%g", style.radius_mm);
      names.emplace_back(name);
      outlines.push_back(random_script(sensor, options.presses_per_family, style));
      radii_mm.push_back(style.radius_mm);
    }
  } else {
    for (std::size_t k = 0; k < outline_families().size(); ++k) {
      OutlineStyle style;
      style.seed = options.seed + 1 + k;
      names.emplace_back(outline_family_name(outline_families()[k]));
      outlines.push_back(outline_script(sensor, outline_families()[k], options.presses_per_family, style));
      radii_mm.push_back(0);
    }
  }
  const PressSequence calibration_presses = calibration_script(sensor, options.calibration_presses, options.seed);

  progress.say("meshing the twin (mesh seed " + std::to_string(options.mesh_seed) + ")");
  TwinOptions twin_options;
  twin_options.mesh_seed = options.mesh_seed;  // finer than and different from the reconstruction's mesh
  twin_options.noise_seed = options.seed;
  Twin twin(sensor, twin_options);
  std::vector<Frame> references;
  references.reserve(static_cast<std::size_t>(options.reference_frames));
  for (int i = 0; i < options.reference_frames; ++i) references.push_back(twin.frame({}));
  const Reference reference = average_reference(references);
  const std::vector<Frame> calibration_frames = simulate(twin, calibration_presses, "calibration press", progress);
  std::vector<std::vector<Frame>> outline_frames;
  for (std::size_t k = 0; k < outlines.size(); ++k)
    outline_frames.push_back(simulate(twin, outlines[k], names[k], progress));

  OutlineEvaluation result;
  result.calibration_presses = options.calibration_presses;
  result.indenters = options.indenters;
  std::vector<std::vector<Vector>> coverage;  // per family and frame, on the reconstruction mesh
  for (const Method method : options.methods) {
    progress.say(std::string("calibrating ") + method_name(method) + " on " +
                 std::to_string(calibration_presses.size()) + " disc presses, as emit calibrate does");
    PressCalibrationOptions calibration_options;  // emit calibrate's defaults
    calibration_options.method = method;
    if (options.calibration_iterations > 0) calibration_options.sensor.max_iterations = options.calibration_iterations;
    const PressCalibrationResult calibration =
        calibrate_from_presses(sensor, calibration_options, reference, calibration_frames, calibration_presses,
                               progress.stage);
    PipelineOptions pipeline_options;
    pipeline_options.method = method;
    const Pipeline pipeline(sensor, pipeline_options, calibration.calibration, progress.stage);
    FrameOptions frame_options;
    frame_options.track_contacts = false;  // each frame on its own, as reconstruct_batch fits them
    Reconstructor reconstructor = pipeline.reconstructor(frame_options);
    reconstructor.set_reference(reference);
    const Mesh& mesh = reconstructor.mesh();
    result.triangles = static_cast<long>(mesh.triangle_count());
    if (coverage.empty() || coverage[0][0].size() != mesh.triangle_count()) {
      coverage.clear();
      for (const PressSequence& family : outlines) {
        coverage.emplace_back();
        for (const std::vector<Press>& presses : family) coverage.back().push_back(outline_coverage(mesh, presses));
      }
    }
    // Contact fitting's methods in the indenter sweep: also with each disc's radius declared.
    for (const bool declared : {false, true}) {
      if (declared && (is_linear(method) || !options.indenters)) break;
      MethodOutlineScore scored;
      scored.method = method;
      scored.declared_radius = declared;
      scored.calibration_rms_N_per_mm2 = calibration.rms_N_per_mm2;
      std::vector<OutlineScore> all;
      const Clock::time_point start = Clock::now();
      for (std::size_t k = 0; k < outlines.size(); ++k) {
        std::optional<Reconstructor> declaring;  // the family's radius declared
        if (declared) {
          FrameOptions o = frame_options;
          o.contact_radius_mm = radii_mm[k];
          declaring.emplace(pipeline.reconstructor(o));
          declaring->set_reference(reference);
        }
        Reconstructor& r = declared ? *declaring : reconstructor;
        std::vector<OutlineScore> scores;
        for (std::size_t f = 0; f < outlines[k].size(); ++f) {
          const std::vector<Contact>& contacts = r.process(outline_frames[k][f]);
          scores.push_back(score_outline_frame(mesh, coverage[k][f], r.pressure(), contacts, outlines[k][f]));
          progress.step(std::string("reconstructing ") + (options.indenters ? "indenters (" : "outlines (") +
                            method_name(method) + (declared ? ", declared radius)" : ")"),
                        static_cast<long>(all.size() + scores.size()),
                        static_cast<long>(outlines.size() * outlines[k].size()));
        }
        scored.families.push_back(summarize_outline_scores(names[k], scores));
        all.insert(all.end(), scores.begin(), scores.end());
      }
      scored.ms_per_frame = 1e3 * std::chrono::duration<double>(Clock::now() - start).count() /
                            static_cast<double>(std::max<std::size_t>(all.size(), 1));
      scored.all = summarize_outline_scores("all", all);
      result.methods.push_back(std::move(scored));
    }
  }
  return result;
}

}  // namespace emit
