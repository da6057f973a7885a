// AllocationCounter: the replaced operator new counts every form, per thread, only while a guard
// is alive. The allocation-free checks elsewhere (ContactFinder::find) are only as good as this.
#include "allocation_counter.hpp"

#include <atomic>
#include <cstdint>
#include <new>
#include <thread>
#include <vector>

#include <gtest/gtest.h>

// The replacement operators, linked exactly once into emit_tests (why: see allocation_counter.cpp).
#include "allocation_counter.cpp"  // NOLINT(bugprone-suspicious-include): on purpose, see above

namespace emit::test {
namespace {

// Stores through a volatile pointer keep the compiler from eliding a new/delete pair, which C++
// allows for new-expressions whose result is unused.
void* volatile sink = nullptr;

struct alignas(64) CacheLine {
  char bytes[64];
};

TEST(AllocationCounter, CountsNothingWhenNothingIsAllocated) {
  const AllocationCounter counter;
  int on_the_stack[16] = {};
  sink = on_the_stack;
  EXPECT_EQ(counter.count(), 0);
  sink = nullptr;  // no dangling pointer to this frame left behind
}

TEST(AllocationCounter, CountsEachFormOfNew) {
  const AllocationCounter counter;
  int* one = new int(1);
  sink = one;
  delete one;
  EXPECT_EQ(counter.count(), 1);
  int* many = new int[10];
  sink = many;
  delete[] many;
  EXPECT_EQ(counter.count(), 2);
  int* nothrow = new (std::nothrow) int(2);
  sink = nothrow;
  delete nothrow;
  EXPECT_EQ(counter.count(), 3);
  std::vector<int> grown(100);
  sink = grown.data();
  EXPECT_EQ(counter.count(), 4);
}

TEST(AllocationCounter, CountsAlignedNewAndAligns) {
  const AllocationCounter counter;
  auto* line = new CacheLine;
  sink = line;
  EXPECT_EQ(reinterpret_cast<std::uintptr_t>(line) % 64, 0u);
  delete line;
  // A size that is not a multiple of the alignment (aligned_alloc needs rounding up under ASan).
  void* odd = ::operator new (10, std::align_val_t{128});
  sink = odd;
  EXPECT_EQ(reinterpret_cast<std::uintptr_t>(odd) % 128, 0u);
  ::operator delete (odd, std::align_val_t{128});
  void* nothrow = ::operator new[](3, std::align_val_t{32}, std::nothrow);
  sink = nothrow;
  ASSERT_NE(nothrow, nullptr);
  ::operator delete[](nothrow, std::align_val_t{32}, std::nothrow);
  EXPECT_EQ(counter.count(), 3);
}

TEST(AllocationCounter, ZeroBytesGiveDistinctPointers) {
  void* a = ::operator new(0);
  void* b = ::operator new(0);
  EXPECT_NE(a, nullptr);
  EXPECT_NE(a, b);
  ::operator delete(a);
  ::operator delete(b);
}

TEST(AllocationCounter, GuardsNest) {
  const AllocationCounter outer;
  sink = new int(1);
  delete static_cast<int*>(sink);
  {
    const AllocationCounter inner;
    sink = new int(2);
    delete static_cast<int*>(sink);
    EXPECT_EQ(inner.count(), 1);
  }
  EXPECT_EQ(outer.count(), 2);
}

TEST(AllocationCounter, IgnoresOtherThreads) {
  std::atomic<bool> go{false}, done{false};
  std::thread other([&] {
    while (!go) std::this_thread::yield();
    sink = new int(3);
    delete static_cast<int*>(sink);
    done = true;
  });
  {
    const AllocationCounter counter;
    go = true;
    while (!done) std::this_thread::yield();
    EXPECT_EQ(counter.count(), 0);
  }
  other.join();
}

}  // namespace
}  // namespace emit::test
