#include "emit/frame/batch.hpp"

#include <exception>
#include <string>
#include <thread>

#include "emit/core/errors.hpp"
#include "emit/core/threads.hpp"

namespace emit {

std::vector<std::vector<Contact>> reconstruct_batch(const ReconstructionModel& model,
                                                    const LinearCalibration& calibration, const FrameOptions& options,
                                                    const Frame& reference, const std::vector<Frame>& frames,
                                                    int threads) {
  if (threads < 1) throw InvalidInput("batch needs at least 1 thread, got " + std::to_string(threads));
  std::vector<std::vector<Contact>> contacts(frames.size());
  std::vector<std::exception_ptr> errors(static_cast<std::size_t>(threads));
  // Contiguous slices: each worker's frames sit together in memory, and its results too.
  const auto work = [&](int worker) {
    try {
      Reconstructor reconstructor(model, calibration, options);
      reconstructor.set_reference(reference);
      const std::size_t begin = frames.size() * static_cast<std::size_t>(worker) / static_cast<std::size_t>(threads);
      const std::size_t end = frames.size() * static_cast<std::size_t>(worker + 1) / static_cast<std::size_t>(threads);
      for (std::size_t f = begin; f < end; ++f) contacts[f] = reconstructor.process(frames[f]);
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

}  // namespace emit
