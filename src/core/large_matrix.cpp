#include "emit/core/large_matrix.hpp"

#include <sys/mman.h>

#include <cstdint>

namespace emit {

void advise_huge_pages(void* data, std::size_t bytes) {
  constexpr std::uintptr_t huge_page = std::uintptr_t{1} << 21;
  const auto start = reinterpret_cast<std::uintptr_t>(data);
  const std::uintptr_t first = (start + huge_page - 1) & ~(huge_page - 1);
  const std::uintptr_t last = (start + bytes) & ~(huge_page - 1);
  // The first whole huge page as a pointer into the same block (no integer-to-pointer cast).
  if (last > first)
    ::madvise(static_cast<char*>(data) + (first - start), last - first, MADV_HUGEPAGE);  // advice: result ignored
}

}  // namespace emit
