#include "emit/core/threads.hpp"

#include <cblas.h>

#include "emit/core/limits.hpp"

namespace emit {

namespace {
int current_count = 1;
}  // namespace

void set_thread_count(int count) {
  limits::check_thread_count("the thread count", count);
  openblas_set_num_threads(count);
  current_count = count;
}

int thread_count() { return current_count; }

SingleThreadedBlas::SingleThreadedBlas() { openblas_set_num_threads(1); }
SingleThreadedBlas::~SingleThreadedBlas() { openblas_set_num_threads(current_count); }

EmitBlasThreads::EmitBlasThreads() : host_count_(openblas_get_num_threads()) {
  if (host_count_ != current_count) openblas_set_num_threads(current_count);
}
EmitBlasThreads::~EmitBlasThreads() {
  if (host_count_ != current_count) openblas_set_num_threads(host_count_);
}

}  // namespace emit
