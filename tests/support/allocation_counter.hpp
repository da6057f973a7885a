#pragma once
// Counting heap allocations in tests, to check that per-frame code allocates nothing.
//
// The global operator new/delete are replaced (allocation_counter.cpp) by versions over malloc/free
// that count, per thread, while at least one AllocationCounter is alive on that thread. Counting per
// thread keeps other threads' allocations out of the count; code under test that spawned a thread
// would still be caught, because creating a std::thread allocates on the spawning thread.

namespace emit::test {

/// Scope guard: count() is the number of operator new calls (every form, including nothrow and
/// aligned) made on this thread since this guard was constructed. Guards nest.
class AllocationCounter {
 public:
  AllocationCounter();
  ~AllocationCounter();
  AllocationCounter(const AllocationCounter&) = delete;
  AllocationCounter& operator=(const AllocationCounter&) = delete;

  long count() const;

 private:
  long start_;
};

}  // namespace emit::test
