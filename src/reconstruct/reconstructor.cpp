#include "emit/reconstruct/reconstructor.hpp"

#include <cmath>

#include "emit/errors.hpp"

namespace emit {

Reconstructor::Reconstructor(const ReconstructionModel& model, PressureCalibration calibration, FrameOptions options)
    : model_(model),
      calibration_(calibration),
      options_(options),
      finder_(model.mesh),
      reference_(Vector::Zero(model.measurements.size())),
      dV_(model.measurements.size()),
      dphi_(model.mesh.triangle_count()),
      pressure_(model.mesh.triangle_count()),
      selected_(static_cast<std::size_t>(model.mesh.triangle_count())) {
  if (!(options.threshold_fraction > 0 && options.threshold_fraction < 1))
    throw InvalidInput("threshold must be a fraction between 0 and 1, got " + std::to_string(options.threshold_fraction));
}

void Reconstructor::set_reference(const Frame& reference) {
  const int N = model_.measurements.electrode_count;
  if (reference.rows() != N || reference.cols() != N)
    throw InvalidInput("reference frame has " + std::to_string(reference.size()) + " values, expected " +
                       std::to_string(N * N));
  if (!reference.allFinite()) throw InvalidInput("reference frame has a value that is not a finite number");
  for (int i = 0; i < model_.measurements.size(); ++i) reference_[i] = reference.data()[model_.measurements.frame_index[i]];
}

const std::vector<Contact>& Reconstructor::process(const Frame& frame) {
  const int N = model_.measurements.electrode_count;
  if (frame.rows() != N || frame.cols() != N)
    throw InvalidInput("frame has " + std::to_string(frame.size()) + " values, expected " + std::to_string(N * N));
  for (int i = 0; i < model_.measurements.size(); ++i)
    dV_[i] = frame.data()[model_.measurements.frame_index[i]] - reference_[i];
  dphi_.noalias() = model_.op * dV_;  // paper eq. 7, precomputed
  const double peak = dphi_.maxCoeff();
  const double threshold = options_.threshold_fraction * peak;
  for (Index k = 0; k < dphi_.size(); ++k) {
    const bool on = peak > 0 && dphi_[k] >= threshold;
    selected_[static_cast<std::size_t>(k)] = on;
    pressure_[k] = on ? calibration_.pressure_N_per_mm2(dphi_[k]) : 0.0;  // paper eq. 8
  }
  return finder_.find(selected_, pressure_, dphi_, options_.min_contact_area_mm2);
}

Frame average_frames(const std::vector<Frame>& frames) {
  if (frames.empty()) throw InvalidInput("no frames to average");
  Frame mean = Frame::Zero(frames[0].rows(), frames[0].cols());
  for (const Frame& f : frames) {
    if (f.rows() != mean.rows() || f.cols() != mean.cols()) throw InvalidInput("frames of different sizes");
    mean += f;
  }
  return mean / static_cast<double>(frames.size());
}

}  // namespace emit
