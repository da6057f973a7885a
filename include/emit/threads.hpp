#pragma once
/// \file threads.hpp
/// How many threads emit's linear algebra may use. The BLAS emit links (OpenBLAS) starts with
/// one per core; emit sets one (the CLI's --threads), so a per-frame product does not pay for
/// waking threads it barely uses, and figures are single-core unless asked otherwise.

namespace emit {

/// \throw InvalidInput unless count ≥ 1.
void set_thread_count(int count);

}  // namespace emit
