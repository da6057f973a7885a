#include "emit/eval/evaluation.hpp"

#include <algorithm>
#include <cmath>

#include "emit/sensor/surface.hpp"

namespace emit {

SimulatedRun simulate_run(Twin& twin, const PressSequence& presses, int reference_frames) {
  SimulatedRun run;
  run.presses = presses;
  std::vector<Frame> references;
  references.reserve(static_cast<std::size_t>(std::max(reference_frames, 0)));
  for (int i = 0; i < reference_frames; ++i) references.push_back(twin.frame({}));
  run.reference = average_reference(references);
  for (const auto& frame_presses : presses) run.frames.push_back(twin.frame(frame_presses));
  return run;
}

Vector3 thresholded_centroid(const Reconstructor& reconstructor, double threshold_fraction) {
  return thresholded_centroid(reconstructor.mesh(), reconstructor.surface(), reconstructor.image(), threshold_fraction);
}

Vector3 thresholded_centroid(const Mesh& mesh, const Shape& surface, const Vector& image, double threshold_fraction) {
  const double threshold = threshold_fraction * image.maxCoeff();
  Vector3 sum = Vector3::Zero();
  double weight = 0;
  for (Index k = 0; k < image.size(); ++k)
    if (image[k] > 0 && image[k] >= threshold) {
      const double w = mesh.triangle_area_mm2(k) * image[k];
      sum += w * mesh.triangle_centroid_mm(k);
      weight += w;
    }
  if (!(weight > 0)) return Vector3::Constant(std::nan(""));
  return surface_point_mm(surface, surface_chart_mm(surface, sum / weight));
}

LocalisationResult localisation_errors(Reconstructor& reconstructor, const SimulatedRun& run,
                                       double threshold_fraction) {
  reconstructor.set_reference(run.reference);
  std::vector<double> image_errors, contact_errors;
  int image_missed = 0, contact_missed = 0;
  for (std::size_t f = 0; f < run.frames.size(); ++f) {
    const Press& truth = run.presses[f].at(0);
    const auto& contacts = reconstructor.process(run.frames[f]);
    const double e = single_press_error_mm(contacts, truth);
    if (e < 0) ++contact_missed;
    else contact_errors.push_back(e);
    const Vector3 c = thresholded_centroid(reconstructor, threshold_fraction);
    if (!c.allFinite()) ++image_missed;
    else image_errors.push_back(position_error_mm(c, truth));
  }
  return {summarize_errors(image_errors, image_missed), summarize_errors(contact_errors, contact_missed)};
}

PressureResult pressure_errors(Reconstructor& reconstructor, const SimulatedRun& calibration_run,
                               const SimulatedRun& test_run, double threshold_fraction) {
  auto samples_of = [&](const SimulatedRun& run) {
    reconstructor.set_reference(run.reference);
    std::vector<PressureSample> samples;
    for (std::size_t f = 0; f < run.frames.size(); ++f) {
      reconstructor.process(run.frames[f]);
      samples.push_back(pressure_sample(reconstructor, threshold_fraction, run.presses[f].at(0).pressure_N_per_mm2()));
    }
    return samples;
  };
  PressureResult result;
  result.fit = fit_pressure_calibration(samples_of(calibration_run));
  std::vector<double> errors;
  for (const auto& s : samples_of(test_run))
    errors.push_back(std::abs(predicted_pressure(result.fit.calibration, s) - s.true_pressure_N_per_mm2));
  result.error_N_per_mm2 = summarize_errors(errors, 0);
  return result;
}

TwoPressResult two_press_rates(Reconstructor& reconstructor, const SimulatedRun& run, double match_mm) {
  reconstructor.set_reference(run.reference);
  TwoPressResult result;
  int two = 0, matched = 0;
  for (std::size_t f = 0; f < run.frames.size(); ++f) {
    const auto& contacts = reconstructor.process(run.frames[f]);
    if (contacts.size() >= 2) ++two;
    bool all = true;
    for (const Press& p : run.presses[f]) {
      bool found = false;
      for (const Contact& c : contacts) found = found || position_error_mm(c, p) <= match_mm;
      all = all && found;
    }
    matched += all;
  }
  result.frames = static_cast<int>(run.frames.size());
  result.two_contacts = result.frames ? double(two) / result.frames : 0;
  result.both_matched = result.frames ? double(matched) / result.frames : 0;
  return result;
}

double every_press_found_rate(Reconstructor& reconstructor, const SimulatedRun& run, double match_mm) {
  reconstructor.set_reference(run.reference);
  int matched = 0;
  for (std::size_t f = 0; f < run.frames.size(); ++f) {
    const auto& contacts = reconstructor.process(run.frames[f]);
    matched += std::all_of(run.presses[f].begin(), run.presses[f].end(), [&](const Press& p) {
      return std::any_of(contacts.begin(), contacts.end(),
                         [&](const Contact& c) { return position_error_mm(c, p) <= match_mm; });
    });
  }
  return run.frames.empty() ? 0 : double(matched) / static_cast<double>(run.frames.size());
}

double extra_contact_rate(Reconstructor& reconstructor, const SimulatedRun& run) {
  reconstructor.set_reference(run.reference);
  int extra = 0;
  for (const Frame& frame : run.frames) extra += reconstructor.process(frame).size() > 1;
  return run.frames.empty() ? 0 : double(extra) / static_cast<double>(run.frames.size());
}

LCurvePoint l_curve_point(const Matrix& J, const CompactOperator& op, const MeasurementSet& measurements,
                          const SimulatedRun& run) {
  LCurvePoint point;
  CompactOperatorScratch scratch = op.scratch();
  Vector dphi;
  for (const Frame& frame : run.frames) {
    const Vector dV = frame_difference(measurements, frame, run.reference.frame);
    op.apply(dV, dphi, scratch);
    point.residual_norm_V += (J * dphi - dV).norm();
    point.solution_norm_V += dphi.norm();
  }
  const double n = std::max<double>(1.0, static_cast<double>(run.frames.size()));
  point.residual_norm_V /= n;
  point.solution_norm_V /= n;
  return point;
}

}  // namespace emit
