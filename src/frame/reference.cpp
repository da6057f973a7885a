#include "emit/frame/reference.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include "emit/core/errors.hpp"
#include "emit/core/option_check.hpp"

namespace emit {

namespace {

/// Which frames average_reference keeps (see there).
std::vector<bool> frames_kept(const std::vector<Frame>& frames) {
  if (frames.empty()) throw InvalidInput("no frames to average");
  for (const Frame& f : frames)
    if (f.rows() != frames[0].rows() || f.cols() != frames[0].cols()) throw InvalidInput("frames of different sizes");
  std::vector<bool> kept(frames.size(), true);
  if (frames.size() < 3) return kept;
  Frame median(frames[0].rows(), frames[0].cols());
  std::vector<double> values;
  values.reserve(frames.size());
  for (Index i = 0; i < median.size(); ++i) {  // over each reading's finite values; NaN if none
    values.clear();
    for (const Frame& f : frames)
      if (std::isfinite(f.data()[i])) values.push_back(f.data()[i]);
    const auto middle = values.begin() + static_cast<std::ptrdiff_t>(values.size() / 2);
    if (!values.empty()) std::nth_element(values.begin(), middle, values.end());
    median.data()[i] = values.empty() ? std::numeric_limits<double>::quiet_NaN() : *middle;
  }
  std::vector<double> distance(frames.size());  // over the readings finite in both
  for (std::size_t f = 0; f < frames.size(); ++f)
    distance[f] = (frames[f] - median).unaryExpr([](double d) { return std::isfinite(d) ? d : 0.0; }).norm();
  std::vector<double> sorted = distance;
  const auto middle = sorted.begin() + static_cast<std::ptrdiff_t>(sorted.size() / 2);
  std::nth_element(sorted.begin(), middle, sorted.end());
  // Pure noise frames' distances agree within a few % (χ with M degrees of freedom), so 3× the
  // median distance leaves them all in and takes out a frame three times as noisy or worse.
  for (std::size_t f = 0; f < frames.size(); ++f) kept[f] = !(distance[f] > 3 * *middle);
  return kept;
}

}  // namespace

Reference average_reference(const std::vector<Frame>& frames) {
  const std::vector<bool> kept = frames_kept(frames);
  Reference reference{Frame::Zero(frames[0].rows(), frames[0].cols()), 0};
  Frame counts = Frame::Zero(frames[0].rows(), frames[0].cols());  // each reading's finite values
  for (std::size_t f = 0; f < frames.size(); ++f) {
    if (!kept[f]) continue;
    reference.frames += 1;
    for (Index i = 0; i < counts.size(); ++i)
      if (std::isfinite(frames[f].data()[i])) reference.frame.data()[i] += frames[f].data()[i], counts.data()[i] += 1;
  }
  // A reading no kept frame held is NaN: masked in every frame (frame/masked_readings.hpp).
  reference.frame.array() /= counts.array();
  return reference;
}

void ReferenceOptions::validate() const {
  option_check::at_least("ReferenceOptions", "capture_frames", capture_frames, 1);
  option_check::within("ReferenceOptions", "drift_rate", drift_rate, 0, 1);
}

ReferenceTracker::ReferenceTracker(ReferenceOptions options) : options_(options) { options_.validate(); }

void ReferenceTracker::recapture() { captured_ = 0; }

bool ReferenceTracker::capture(const Frame& frame) {
  if (captured_ > 0 && (frame.rows() != captured_frames_[0].rows() || frame.cols() != captured_frames_[0].cols()))
    throw InvalidInput("reference: a frame of another size during the capture");
  const auto at = static_cast<std::size_t>(captured_);
  if (captured_frames_.size() <= at) captured_frames_.resize(at + 1);
  captured_frames_[at] = frame;
  if (++captured_ < options_.capture_frames) return false;
  reference_ = average_reference(captured_frames_);
  ++captures_;
  return true;
}

bool ReferenceTracker::follow(const Frame& frame, bool touched) {
  if (!ready()) throw InvalidInput("reference: no reference captured yet");
  if (frame.rows() != reference_.frame.rows() || frame.cols() != reference_.frame.cols())
    throw InvalidInput("reference: a frame of another size than the reference");
  const double r = options_.drift_rate;
  if (touched || r == 0) return false;
  for (Index i = 0; i < frame.size(); ++i)  // a reading not finite leaves its reference as it was
    if (std::isfinite(frame.data()[i]))
      reference_.frame.data()[i] += r * (frame.data()[i] - reference_.frame.data()[i]);
  // Var(V_ref) ← (1 − r)² Var(V_ref) + r² σ², in units of one frame's σ²: it falls from 1/n toward
  // r/(2 − r) (199 frames' worth at r = 0.01).
  reference_.frames = 1 / ((1 - r) * (1 - r) / reference_.frames + r * r);
  return true;
}

}  // namespace emit
