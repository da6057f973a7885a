// The sizes a user can ask for (core/limits.hpp): each bound said in one line that names the
// option and the limit, and refused before anything is set or allocated.
#include "emit/core/limits.hpp"

#include <cmath>
#include <string>

#include <gtest/gtest.h>

#include "emit/core/errors.hpp"
#include "emit/core/threads.hpp"
#include "test_support.hpp"

namespace emit {
namespace {

TEST(Limits, AThreadCountIsFromOneTo256AndSaysWhy) {
  EXPECT_NO_THROW(limits::check_thread_count("threads", 1));
  EXPECT_NO_THROW(limits::check_thread_count("threads", limits::max_threads));
  EXPECT_EQ(test::error_of([] { limits::check_thread_count("threads", 4096); }),
            "threads must be a whole number from 1 to 256 (threads beyond the cores only cost memory), got 4096");
  EXPECT_EQ(test::error_of([] { limits::check_thread_count("threads", 0); }),
            "threads must be a whole number from 1 to 256 (threads beyond the cores only cost memory), got 0");
  // The process's count is refused as a batch's is, and stays what it was (it was set, BLAS's
  // buffers and all, before: --threads 1000000000 took 4 GB).
  const int before = thread_count();
  EXPECT_THROW(set_thread_count(1'000'000'000), InvalidInput);
  EXPECT_EQ(thread_count(), before);
}

TEST(Limits, FramesHeldAre256MiBOfReadings) {
  EXPECT_EQ(limits::max_frames_held(16), 131072);
  EXPECT_EQ(limits::max_frames_held(32), 32768);
  EXPECT_EQ(limits::max_frames_held(0), limits::max_frames_held(1));  // no electrodes read yet: no division by 0
  EXPECT_NO_THROW(limits::check_frames_held("--frames 131072", 131072, 16, ""));
  EXPECT_EQ(test::error_of([] { limits::check_frames_held("--frames 1000000000", 1e9, 16, "simulate in parts"); }),
            "--frames 1000000000: 1000000000 frames of 16 electrodes, beyond the 131072 a run holds in memory (256 MiB "
            "of readings); simulate in parts");
  // A count past a double's integers, or not a number, is refused too, and printed short.
  EXPECT_EQ(test::error_of([] { limits::check_frames_held("n", 1e300, 16, ""); }),
            "n: 1e+300 frames of 16 electrodes, beyond the 131072 a run holds in memory (256 MiB of readings)");
  EXPECT_THROW(limits::check_frames_held("n", std::nan(""), 16, ""), InvalidInput);
}

}  // namespace
}  // namespace emit
