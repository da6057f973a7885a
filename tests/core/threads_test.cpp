// The thread count (core/threads.hpp): set, read back, refused below one, and held at one by
// SingleThreadedBlas only while it lives.
#include "emit/core/threads.hpp"

#include <string>

#include <cblas.h>

#include <gtest/gtest.h>

#include "emit/core/errors.hpp"

namespace emit {
namespace {

TEST(Threads, SetReadBackAndSingleThreadedScope) {
  const int before = thread_count();
  set_thread_count(2);
  EXPECT_EQ(thread_count(), 2);
  EXPECT_EQ(openblas_get_num_threads(), 2);
  {
    SingleThreadedBlas single;
    EXPECT_EQ(openblas_get_num_threads(), 1);
    EXPECT_EQ(thread_count(), 2);  // the count set stays; only BLAS is held at one
  }
  EXPECT_EQ(openblas_get_num_threads(), 2);
  std::string message = "no error";
  try {
    set_thread_count(0);
  } catch (const InvalidInput& e) {
    message = e.what();
  }
  EXPECT_EQ(message,
            "the thread count must be a whole number from 1 to 256 (threads beyond the cores only cost memory), got 0");
  EXPECT_EQ(thread_count(), 2);
  set_thread_count(before);
}

}  // namespace
}  // namespace emit
