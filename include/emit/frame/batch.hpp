#pragma once
/// \file batch.hpp
/// A block of independent frames reconstructed on several threads: contiguous slices, one
/// Reconstructor per worker. Each frame's contacts are what one reconstructor gives it alone, so
/// the result does not depend on the thread count (contact fitting fits every frame cold: tracking
/// from frame to frame would make a slice's first frame differ; Pipeline::reconstruct_batch turns
/// it off).
#include <functional>
#include <span>
#include <vector>

#include "emit/frame/reconstructor.hpp"

namespace emit {

/// Makes one worker's reconstructor; called once per worker, on its thread.
using ReconstructorFactory = std::function<Reconstructor()>;

/// Contacts of every frame, in order, with `threads` workers, each reconstructing against
/// `reference`. \throw InvalidInput for a thread count outside 1 … limits::max_threads (core/limits.hpp) or
/// a bad frame; the first worker's error.
std::vector<std::vector<Contact>> reconstruct_batch(const ReconstructorFactory& make, const Reference& reference,
                                                    const std::vector<Frame>& frames, int threads);

/// The same for frames held as one block: `frames_volts` holds frame after frame, each N×N
/// ground-major (a C-ordered (frames, N, N) array), read in place. \throw InvalidInput also when
/// its length is not a whole number of frames.
std::vector<std::vector<Contact>> reconstruct_batch(const ReconstructorFactory& make, const Reference& reference,
                                                    std::span<const double> frames_volts, Index electrodes,
                                                    int threads);

/// A linear method's batch (eq. 7 with `calibration`).
std::vector<std::vector<Contact>> reconstruct_batch(const ReconstructionModel& model,
                                                    const LinearCalibration& calibration, const FrameOptions& options,
                                                    const Reference& reference, const std::vector<Frame>& frames,
                                                    int threads);

}  // namespace emit
