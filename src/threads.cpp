#include "emit/threads.hpp"

#include <cblas.h>

#include <string>

#include "emit/errors.hpp"

namespace emit {

void set_thread_count(int count) {
  if (count < 1) throw InvalidInput("thread count must be at least 1, got " + std::to_string(count));
  openblas_set_num_threads(count);
}

}  // namespace emit
