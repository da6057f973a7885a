// Replacement global operator new/delete that count allocations (see allocation_counter.hpp).
//
// Not compiled on its own: the test target takes tests/*_test.cpp plus test_support.cpp, so this
// file is #included by exactly one test file, allocation_counter_test.cpp. That keeps the
// replacements in a file of their own (rather than mixed into a test) while linking them exactly
// once into emit_tests. Should the target ever list this file, drop that #include: a second copy
// would fail to link (duplicate operator new), so the mistake cannot go unnoticed.
//
// AddressSanitizer: replacing operator new is allowed; ASan still intercepts the malloc, free and
// aligned_alloc underneath, so overflows, use-after-free and leaks are still found (only its
// new/delete mismatch check is lost).
#include "allocation_counter.hpp"

#include <cstddef>
#include <cstdlib>
#include <new>

namespace {

// Constant-initialised thread_locals: reading them in operator new allocates nothing and needs no
// dynamic initialisation, so they are safe however early the first allocation happens.
thread_local int active_guards = 0;
thread_local long allocations = 0;

void note_allocation() noexcept {
  if (active_guards > 0) ++allocations;
}

/// operator new must return a unique pointer even for 0 bytes, where malloc may return null.
std::size_t at_least_one(std::size_t size) noexcept { return size == 0 ? 1 : size; }

/// aligned_alloc wants the size a multiple of the alignment (ASan enforces it; glibc does not).
std::size_t round_up(std::size_t size, std::align_val_t alignment) noexcept {
  const auto a = static_cast<std::size_t>(alignment);
  return (at_least_one(size) + a - 1) / a * a;
}

void* try_allocate(std::size_t size) noexcept { return std::malloc(at_least_one(size)); }

void* try_allocate(std::size_t size, std::align_val_t alignment) noexcept {
  return std::aligned_alloc(static_cast<std::size_t>(alignment), round_up(size, alignment));
}

/// The throwing forms' contract: call the new-handler until it frees memory or there is none.
template <class... Alignment>
void* allocate_or_throw(std::size_t size, Alignment... alignment) {
  note_allocation();
  for (;;) {
    if (void* p = try_allocate(size, alignment...)) return p;
    const std::new_handler handler = std::get_new_handler();
    if (handler == nullptr) throw std::bad_alloc();
    handler();
  }
}

template <class... Alignment>
void* allocate_or_null(std::size_t size, Alignment... alignment) noexcept {
  try {
    return allocate_or_throw(size, alignment...);
  } catch (...) {  // the nothrow forms report failure (also a new-handler's bad_alloc) as null
    return nullptr;
  }
}

}  // namespace

namespace emit::test {

AllocationCounter::AllocationCounter() : start_(allocations) { ++active_guards; }
AllocationCounter::~AllocationCounter() { --active_guards; }
long AllocationCounter::count() const { return allocations - start_; }

}  // namespace emit::test

// Every replaceable form ([new.delete.single], [new.delete.array]); all memory is malloc's or
// aligned_alloc's, so every delete form is free().
void* operator new(std::size_t size) { return allocate_or_throw(size); }
void* operator new[](std::size_t size) { return allocate_or_throw(size); }
void* operator new(std::size_t size, const std::nothrow_t&) noexcept { return allocate_or_null(size); }
void* operator new[](std::size_t size, const std::nothrow_t&) noexcept { return allocate_or_null(size); }
void* operator new(std::size_t size, std::align_val_t a) { return allocate_or_throw(size, a); }
void* operator new[](std::size_t size, std::align_val_t a) { return allocate_or_throw(size, a); }
void* operator new(std::size_t size, std::align_val_t a, const std::nothrow_t&) noexcept {
  return allocate_or_null(size, a);
}
void* operator new[](std::size_t size, std::align_val_t a, const std::nothrow_t&) noexcept {
  return allocate_or_null(size, a);
}

void operator delete(void* p) noexcept { std::free(p); }
void operator delete[](void* p) noexcept { std::free(p); }
void operator delete(void* p, const std::nothrow_t&) noexcept { std::free(p); }
void operator delete[](void* p, const std::nothrow_t&) noexcept { std::free(p); }
void operator delete(void* p, std::size_t) noexcept { std::free(p); }
void operator delete[](void* p, std::size_t) noexcept { std::free(p); }
void operator delete(void* p, std::align_val_t) noexcept { std::free(p); }
void operator delete[](void* p, std::align_val_t) noexcept { std::free(p); }
void operator delete(void* p, std::size_t, std::align_val_t) noexcept { std::free(p); }
void operator delete[](void* p, std::size_t, std::align_val_t) noexcept { std::free(p); }
void operator delete(void* p, std::align_val_t, const std::nothrow_t&) noexcept { std::free(p); }
void operator delete[](void* p, std::align_val_t, const std::nothrow_t&) noexcept { std::free(p); }
