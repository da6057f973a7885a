#pragma once
/// \file linear_robustness.hpp
/// What `emit eval` measures of a linear method beyond its positional error (docs/physics.md,
/// "The linear methods per frame"): contacts where there is no press (ghosts), and how much the
/// result depends on which no-contact frames made the reference.
#include <vector>

#include "emit/eval/evaluation.hpp"

namespace emit {

/// The fraction of frames with a contact that is not a press (has_false_contact,
/// contact_scoring.hpp), against the run's reference.
double false_contact_rate(Reconstructor& reconstructor, const SimulatedRun& run, double distance_mm);

/// The paper's positional error (localisation_errors' image centroid) when the reference is
/// each one of `references` alone, single frames: the lowest and highest mean.
struct ReferenceSpread {
  double low_mm = 0, high_mm = 0;
};
ReferenceSpread single_reference_spread(Reconstructor& reconstructor, const SimulatedRun& run,
                                        const std::vector<Frame>& references);

/// The same error with the reference averaged (average_reference) from `references`, the first of
/// them made very noisy (`extra_noise_V` of Gaussian noise added, seeded).
double noisy_reference_error_mm(Reconstructor& reconstructor, const SimulatedRun& run, std::vector<Frame> references,
                                double extra_noise_V, std::uint64_t seed);

}  // namespace emit
