#include "emit/eval/linear_robustness.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>

#include "emit/eval/contact_scoring.hpp"

namespace emit {

namespace {

/// localisation_errors' image-centroid mean, against `reference`.
double position_error_mm(Reconstructor& reconstructor, const SimulatedRun& run, const Reference& reference) {
  std::vector<double> errors;
  int missed = 0;
  reconstructor.set_reference(reference);
  for (std::size_t f = 0; f < run.frames.size(); ++f) {
    const Press& truth = run.presses[f].at(0);
    reconstructor.process(run.frames[f]);
    const Vector3 c = thresholded_centroid(reconstructor, 0.5);
    if (!c.allFinite()) ++missed;
    else errors.push_back(position_error_mm(c, truth));
  }
  return summarize_errors(errors, missed).mean;
}

}  // namespace

double false_contact_rate(Reconstructor& reconstructor, const SimulatedRun& run, double distance_mm) {
  reconstructor.set_reference(run.reference);
  int ghosts = 0;
  for (std::size_t f = 0; f < run.frames.size(); ++f)
    ghosts += has_false_contact(reconstructor.process(run.frames[f]), run.presses[f], distance_mm);
  return run.frames.empty() ? 0.0 : static_cast<double>(ghosts) / static_cast<double>(run.frames.size());
}

ReferenceSpread single_reference_spread(Reconstructor& reconstructor, const SimulatedRun& run,
                                        const std::vector<Frame>& references) {
  ReferenceSpread spread{std::numeric_limits<double>::infinity(), 0};
  for (const Frame& reference : references) {
    const double e = position_error_mm(reconstructor, run, {reference, 1});
    spread.low_mm = std::min(spread.low_mm, e);
    spread.high_mm = std::max(spread.high_mm, e);
  }
  return spread;
}

double noisy_reference_error_mm(Reconstructor& reconstructor, const SimulatedRun& run, std::vector<Frame> references,
                                double extra_noise_V, std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::normal_distribution<double> noise(0.0, extra_noise_V);
  if (!references.empty())
    for (Index i = 0; i < references[0].size(); ++i) references[0].data()[i] += noise(rng);
  return position_error_mm(reconstructor, run, average_reference(references));
}

}  // namespace emit
