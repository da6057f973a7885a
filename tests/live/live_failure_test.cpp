// The live loop never takes a failure for an end (issue 32: a failed simulator ended `emit live`
// with a normal summary and exit 0). A source that fails throws out of run() with its message,
// stats() telling what was done before; a source that ends (a recording's end) returns normally;
// a publisher's failure ends the run as the source's does.
#include <atomic>
#include <chrono>
#include <string>
#include <utility>

#include <gtest/gtest.h>

#include "emit/core/errors.hpp"
#include "emit/live/live_loop.hpp"
#include "emit/sensor/sensor_json.hpp"
#include "test_support.hpp"

namespace emit {
namespace {

/// Hands out `frames` untouched frames, then ends (finished()) or fails (next() throws, for good).
class ScriptedEnd : public FrameSource {
 public:
  ScriptedEnd(int electrodes, std::uint64_t frames, bool fails) : frames_(frames), fails_(fails) {
    volts_ = Frame::Constant(electrodes, electrodes, 1.0);
    volts_.diagonal().setZero();
  }
  bool next(SourceFrame& frame, std::chrono::milliseconds) override {
    if (sent_ == frames_) throw IoError(fails_ ? "scripted: the board caught fire" : "scripted: end");
    frame.volts = volts_;
    frame.sequence = sent_++;
    frame.received = std::chrono::steady_clock::now();
    return true;
  }
  bool finished() const override { return !fails_ && sent_ == frames_; }
  std::string description() const override { return "scripted"; }

 private:
  Frame volts_;
  std::uint64_t frames_, sent_ = 0;
  bool fails_;
};

/// Counts what it is given; throws at the `fail_at`-th frame (0: never).
class CountingPublisher : public FramePublisher {
 public:
  explicit CountingPublisher(std::uint64_t fail_at = 0) : fail_at_(fail_at) {}
  void publish(const LiveFrame&) override {
    if (++published == fail_at_) throw IoError("--mcap m.mcap: write failed (No space left on device)");
  }
  std::uint64_t published = 0;

 private:
  std::uint64_t fail_at_;
};

Pipeline& pipeline() {
  static Pipeline p(default_sensor(),
                    {.method = Method::paper, .cache_dir = test::temp_folder("live_failure_cache"), .excluded = {}});
  return p;
}

// 25 frames, 10 of them the reference's capture: ended, run() returns 15 reconstructed frames;
// failed, run() throws the source's message and stats() holds the same 15.
TEST(LiveFailure, AFailedSourceIsNoEnd) {
  const int capture = ReferenceOptions{}.capture_frames;
  const std::atomic<bool> stop{false};
  {
    ScriptedEnd source(16, 25, /*fails=*/false);
    LiveLoop loop(source, pipeline());
    EXPECT_EQ(loop.run(stop).frames, 25u - capture);
  }
  ScriptedEnd source(16, 25, /*fails=*/true);
  LiveLoop loop(source, pipeline());
  CountingPublisher publisher;
  loop.add_publisher(&publisher);
  try {
    loop.run(stop);
    FAIL() << "a failed source ended the run quietly";
  } catch (const IoError& e) {
    EXPECT_STREQ(e.what(), "scripted: the board caught fire");
  }
  EXPECT_EQ(loop.stats().frames, 25u - capture);
  EXPECT_EQ(loop.stats().capture_frames, static_cast<std::uint64_t>(capture));
  EXPECT_EQ(publisher.published, 25u);
}

// A publisher (the MCAP file, DDS) that fails at its 12th frame ends the run with its message.
TEST(LiveFailure, AFailedPublisherEndsTheRun) {
  ScriptedEnd source(16, 100, /*fails=*/false);
  LiveLoop loop(source, pipeline());
  CountingPublisher publisher(12);
  loop.add_publisher(&publisher);
  const std::atomic<bool> stop{false};
  try {
    loop.run(stop);
    FAIL() << "a failed publisher ended the run quietly";
  } catch (const IoError& e) {
    EXPECT_STREQ(e.what(), "--mcap m.mcap: write failed (No space left on device)");
  }
  EXPECT_EQ(publisher.published, 12u);
  EXPECT_EQ(loop.stats().frames, 12u - ReferenceOptions{}.capture_frames - 1);  // the 12th failed before it counted
}

}  // namespace
}  // namespace emit
