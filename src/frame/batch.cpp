#include "emit/frame/batch.hpp"

#include <exception>
#include <string>
#include <thread>

#include "emit/core/errors.hpp"
#include "emit/core/limits.hpp"
#include "emit/core/threads.hpp"

namespace emit {

namespace {

/// The batch over `count` frames, `frame(f)` giving frame f (a Frame or a FrameView).
template <typename FrameAt>
std::vector<std::vector<Contact>> batch(const ReconstructorFactory& make, const Reference& reference, std::size_t count,
                                        int threads, const FrameAt& frame) {
  limits::check_thread_count("threads", threads);
  std::vector<std::vector<Contact>> contacts(count);
  std::vector<std::exception_ptr> errors(static_cast<std::size_t>(threads));
  // Contiguous slices: each worker's frames sit together in memory, and its results too.
  const auto work = [&](int worker) {
    try {
      Reconstructor reconstructor = make();
      reconstructor.set_reference(reference);
      const std::size_t begin = count * static_cast<std::size_t>(worker) / static_cast<std::size_t>(threads);
      const std::size_t end = count * static_cast<std::size_t>(worker + 1) / static_cast<std::size_t>(threads);
      for (std::size_t f = begin; f < end; ++f) contacts[f] = reconstructor.process(frame(f));
    } catch (...) {
      errors[static_cast<std::size_t>(worker)] = std::current_exception();
    }
  };
  const SingleThreadedBlas one_blas_thread_per_worker;
  std::vector<std::thread> pool;
  for (int worker = 1; worker < threads; ++worker) pool.emplace_back(work, worker);
  work(0);
  for (std::thread& thread : pool) thread.join();
  for (const std::exception_ptr& error : errors)
    if (error) std::rethrow_exception(error);
  return contacts;
}

}  // namespace

std::vector<std::vector<Contact>> reconstruct_batch(const ReconstructorFactory& make, const Reference& reference,
                                                    const std::vector<Frame>& frames, int threads) {
  return batch(make, reference, frames.size(), threads, [&](std::size_t f) -> const Frame& { return frames[f]; });
}

std::vector<std::vector<Contact>> reconstruct_batch(const ReconstructorFactory& make, const Reference& reference,
                                                    std::span<const double> frames_volts, Index electrodes,
                                                    int threads) {
  const Index N = electrodes;
  const auto per_frame = static_cast<std::size_t>(N * N);
  if (per_frame == 0 || frames_volts.size() % per_frame != 0)
    throw InvalidInput("frames: " + std::to_string(frames_volts.size()) + " values are not a whole number of " +
                       std::to_string(N) + " × " + std::to_string(N) + " frames");
  return batch(make, reference, frames_volts.size() / per_frame, threads,
               [&](std::size_t f) { return FrameView(frames_volts.data() + f * per_frame, N, N); });
}

std::vector<std::vector<Contact>> reconstruct_batch(const ReconstructionModel& model,
                                                    const LinearCalibration& calibration, const FrameOptions& options,
                                                    const Reference& reference, const std::vector<Frame>& frames,
                                                    int threads) {
  return reconstruct_batch([&] { return Reconstructor(model, calibration, options); }, reference, frames, threads);
}

}  // namespace emit
