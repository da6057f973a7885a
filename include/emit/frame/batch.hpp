#pragma once
/// \file batch.hpp
/// A recorded file's frames at full speed: the linear methods treat each frame on its own, so a
/// batch is split across threads, each with its own Reconstructor on the shared model.
#include <span>
#include <vector>

#include "emit/frame/reconstructor.hpp"

namespace emit {

/// Contacts of every frame, in order, with `threads` workers (each frame's contacts are those
/// one Reconstructor would give). For the linear methods only: contact fitting tracks from
/// frame to frame and runs in order. \throw InvalidInput for threads < 1 or a bad frame.
std::vector<std::vector<Contact>> reconstruct_batch(const ReconstructionModel& model,
                                                    const LinearCalibration& calibration, const FrameOptions& options,
                                                    const Frame& reference, const std::vector<Frame>& frames,
                                                    int threads);

/// The same for frames held as one block: `frames_volts` holds frame after frame, each N×N
/// ground-major (a C-ordered (frames, N, N) array), read in place. \throw InvalidInput also when
/// its length is not a whole number of frames.
std::vector<std::vector<Contact>> reconstruct_batch(const ReconstructionModel& model,
                                                    const LinearCalibration& calibration, const FrameOptions& options,
                                                    const Frame& reference, std::span<const double> frames_volts,
                                                    int threads);

}  // namespace emit
