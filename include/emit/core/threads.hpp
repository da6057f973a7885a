#pragma once
/// \file threads.hpp
/// How many threads emit's linear algebra may use. The BLAS emit links (OpenBLAS) starts with
/// one per core; emit sets one (the CLI's --threads), so a per-frame product does not pay for
/// waking threads it barely uses, and figures are single-core unless asked otherwise.

namespace emit {

/// \throw InvalidInput unless 1 ≤ count ≤ limits::max_threads (core/limits.hpp).
void set_thread_count(int count);
/// The count last set (1 until set).
int thread_count();

/// While alive, BLAS uses one thread a call (for code that runs threads of its own, so the two
/// do not oversubscribe the cores); the count set before comes back after.
class SingleThreadedBlas {
 public:
  SingleThreadedBlas();
  ~SingleThreadedBlas();
  SingleThreadedBlas(const SingleThreadedBlas&) = delete;
  SingleThreadedBlas& operator=(const SingleThreadedBlas&) = delete;
};

/// While alive, BLAS uses thread_count() threads a call, and the BLAS's own count from before
/// comes back after: for emit called from a host that shares the BLAS and sets its own count
/// (numpy, in the Python module), so that emit's figures are the CLI's and the host's are its own.
class EmitBlasThreads {
 public:
  EmitBlasThreads();
  ~EmitBlasThreads();
  EmitBlasThreads(const EmitBlasThreads&) = delete;
  EmitBlasThreads& operator=(const EmitBlasThreads&) = delete;

 private:
  int host_count_;
};

}  // namespace emit
