#include "emit/live/baseline.hpp"

#include "emit/core/errors.hpp"

namespace emit {

Baseline::Baseline(BaselineOptions options) : options_(options) {
  if (options_.capture_frames < 1) throw InvalidInput("baseline: capture frames must be at least 1");
  if (!(options_.drift_rate >= 0 && options_.drift_rate <= 1))
    throw InvalidInput("baseline: drift rate must be in [0, 1]");
}

void Baseline::recapture() { captured_ = 0; }

bool Baseline::capture(const Frame& frame) {
  if (captured_ == 0) {
    sum_ = frame;
  } else {
    if (frame.rows() != sum_.rows() || frame.cols() != sum_.cols())
      throw InvalidInput("baseline: a frame of another size during the capture");
    sum_ += frame;
  }
  if (++captured_ < options_.capture_frames) return false;
  reference_ = sum_ / static_cast<double>(captured_);
  ++captures_;
  return true;
}

bool Baseline::follow(const Frame& frame, bool touched) {
  if (!ready()) throw InvalidInput("baseline: no reference captured yet");
  if (frame.rows() != reference_.rows() || frame.cols() != reference_.cols())
    throw InvalidInput("baseline: a frame of another size than the reference");
  if (touched || options_.drift_rate == 0) return false;
  reference_ += options_.drift_rate * (frame - reference_);
  return true;
}

}  // namespace emit
