#include "emit/frame/press_segmenter.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <string>

#include "emit/core/errors.hpp"
#include "emit/core/option_check.hpp"

namespace emit {

void PressSegmenterOptions::validate() const {
  const char* owner = "PressSegmenterOptions";
  option_check::positive(owner, "lift_factor", lift_factor);
  option_check::within(owner, "press_factor", press_factor, lift_factor, 1e12);
  option_check::non_negative(owner, "stable_noise_factor", stable_noise_factor);
  option_check::non_negative(owner, "stable_fraction", stable_fraction);
  option_check::at_least(owner, "trim_frames", trim_frames, 0);
  option_check::at_least(owner, "min_frames", min_frames, 2 * static_cast<std::int64_t>(trim_frames) + 1);
}

PressSegmenter::PressSegmenter(const Reference& reference, double reading_noise_V, PressSegmenterOptions options)
    : options_(options), reference_(reference.frame), noise_V_(reading_noise_V) {
  options_.validate();
  if (reference_.rows() != reference_.cols() || reference_.rows() < 2)
    throw InvalidInput("press segmentation: the reference must be an N x N frame with N >= 2, got " +
                       std::to_string(reference_.rows()) + " x " + std::to_string(reference_.cols()));
  if (!(reading_noise_V > 0) || !std::isfinite(reading_noise_V))
    throw InvalidInput("press segmentation: a reading's noise must be positive, got " +
                       std::to_string(reading_noise_V) + " V");
  if (!(reference.frames > 0)) throw InvalidInput("press segmentation: the reference must hold a frame or more");
  untouched_noise_V_ = noise_V_ * std::sqrt(1 + 1 / reference.frames);
  const Index N = reference_.rows();
  previous_ = sum_ = best_sum_ = press_.frame = Frame::Zero(N, N);
  delayed_.assign(static_cast<std::size_t>(options_.trim_frames), Frame::Zero(N, N));
}

double PressSegmenter::rms_difference(const FrameView& a, const FrameView& b) const {
  const Index N = reference_.rows();
  double sum = 0;
  for (Index l = 0; l < N; ++l)
    for (Index m = 0; m < N; ++m)
      if (l != m) sum += (a(l, m) - b(l, m)) * (a(l, m) - b(l, m));
  return std::sqrt(sum / static_cast<double>(N * (N - 1)));
}

void PressSegmenter::end_run() {
  if (run_ >= options_.min_frames && run_ > best_run_) {
    best_sum_ = sum_;
    best_run_ = run_;
    best_first_ = run_first_;
  }
  run_ = 0;
  sum_.setZero();
}

bool PressSegmenter::push(const FrameView& frame) {
  if (frame.rows() != reference_.rows() || frame.cols() != reference_.cols())
    throw InvalidInput("press segmentation: frame " + std::to_string(frames_seen_) + " is " +
                       std::to_string(frame.rows()) + " x " + std::to_string(frame.cols()) + ", the reference " +
                       std::to_string(reference_.rows()) + " x " + std::to_string(reference_.cols()));
  const std::uint64_t k = frames_seen_++;
  change_rms_V_ = rms_difference(frame, frame_view(reference_));
  const double step_V =
      have_previous_ ? rms_difference(frame, frame_view(previous_)) : std::numeric_limits<double>::infinity();
  previous_ = frame;
  have_previous_ = true;
  if (!touched_) {
    if (change_rms_V_ <= press_threshold_V()) return false;
    touched_ = true;  // landing: this frame differs from the last, so a run starts after it
    best_run_ = run_ = 0;
    sum_.setZero();
    return false;
  }
  if (change_rms_V_ < lift_threshold_V()) {  // lifted: the touch's longest stable run is its press
    end_run();
    touched_ = false;
    if (best_run_ == 0) return false;
    const int averaged = best_run_ - 2 * options_.trim_frames;
    press_.frame = best_sum_ / averaged;
    press_.first_frame = best_first_;
    press_.last_frame = best_first_ + static_cast<std::uint64_t>(best_run_) - 1;
    press_.frames_averaged = averaged;
    press_.change_rms_V = rms_difference(frame_view(press_.frame), frame_view(reference_));
    best_run_ = 0;
    return true;
  }
  const bool stable =
      change_rms_V_ > press_threshold_V() &&
      step_V < options_.stable_noise_factor * std::numbers::sqrt2 * noise_V_ + options_.stable_fraction * change_rms_V_;
  if (!stable) {
    end_run();
    return false;
  }
  if (run_ == 0) run_first_ = k;
  ++run_;
  // The first trim_frames of the run are left out; every later frame waits trim_frames in the
  // ring before it joins the sum, so the last trim_frames are never in it.
  const int trim = options_.trim_frames;
  if (run_ <= trim) return false;
  if (trim == 0) {
    sum_ += frame;
    return false;
  }
  Frame& slot = delayed_[static_cast<std::size_t>((run_ - trim - 1) % trim)];
  if (run_ > 2 * trim) sum_ += slot;
  slot = frame;
  return false;
}

double measured_reading_noise_V(const std::vector<Frame>& quiet_frames) {
  if (quiet_frames.size() < 2)
    throw InvalidInput("a reading's noise needs 2 or more quiet frames, got " + std::to_string(quiet_frames.size()));
  const Frame& first = quiet_frames.front();
  Frame mean = Frame::Zero(first.rows(), first.cols());
  for (const Frame& f : quiet_frames) {
    if (f.rows() != first.rows() || f.cols() != first.cols())
      throw InvalidInput("quiet frames of different sizes: " + std::to_string(first.rows()) + " and " +
                         std::to_string(f.rows()) + " electrodes");
    mean += f;
  }
  mean /= static_cast<double>(quiet_frames.size());
  const Index N = first.rows();
  double sum = 0;
  for (const Frame& f : quiet_frames)
    for (Index l = 0; l < N; ++l)
      for (Index m = 0; m < N; ++m)
        if (l != m) sum += (f(l, m) - mean(l, m)) * (f(l, m) - mean(l, m));
  const auto readings = static_cast<double>(N * (N - 1));
  return std::sqrt(sum / (readings * static_cast<double>(quiet_frames.size() - 1)));
}

}  // namespace emit
