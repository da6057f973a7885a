#pragma once
/// \file reconstructor.hpp
/// The online half (DESIGN §6): per frame, δV = V − V_ref → δφ = R·δV → threshold → pressure
/// (eq. 8) → contacts. It allocates nothing per frame: every buffer is sized at construction.
#include <cstdint>
#include <vector>

#include "emit/fem/forward_model.hpp"
#include "emit/fit/contact_fitter.hpp"
#include "emit/reconstruct/contacts.hpp"
#include "emit/reconstruct/pressure.hpp"
#include "emit/reconstruct/reconstruction_model.hpp"

namespace emit {

struct FrameOptions {
  double threshold_fraction = 0.5;  ///< of the image's maximum (paper §2.4)
  double min_contact_area_mm2 = 0;  ///< smaller regions are dropped
  /// With a fitter: start each frame from the last frame's contacts (ContactFitter::track), and
  /// seed afresh from the linear image only when that does not explain the frame. A stream of
  /// frames from a moving finger then costs a fraction of a cold fit; frames that are not a stream
  /// cost one tracking attempt more. While tracking holds, the linear image is not computed.
  bool track_contacts = true;
};

class Reconstructor {
 public:
  /// Keeps a reference to `model`, which must outlive it. \throw InvalidInput for a bad option.
  Reconstructor(const ReconstructionModel& model, PressureCalibration calibration, FrameOptions options = {});

  /// The no-contact reference frame. \throw InvalidInput if it is not N×N or not finite.
  void set_reference(const Frame& reference);

  /// Contacts by model-based fitting (contact_fitter.hpp), seeded by the linear image's contacts,
  /// instead of from the thresholded image. `fitter` must outlive this and use the same
  /// measurements; null turns fitting off.
  void use_fitter(ContactFitter* fitter) { fitter_ = fitter; }
  /// The last frame's fit (valid when a fitter is in use).
  const FitResult* fit_result() const { return fitter_ ? &fitter_result_ : nullptr; }

  /// One frame → contacts (valid until the next call). \throw InvalidInput if the frame is not
  /// N×N; the frame's values are not checked here (the readers check them).
  const std::vector<Contact>& process(const Frame& frame);

  const Vector& image() const { return dphi_; }       ///< δφ per element [V] (0 while tracking holds)
  const Vector& pressure() const { return pressure_; } ///< per element [N/mm²], 0 below threshold
  const Mesh& mesh() const { return model_.mesh; }

 private:
  const ReconstructionModel& model_;
  PressureCalibration calibration_;
  FrameOptions options_;
  ContactFinder finder_;
  Vector reference_, dV_, dphi_, pressure_;
  std::vector<std::uint8_t> selected_;
  ContactFitter* fitter_ = nullptr;
  FitResult fitter_result_;
  std::vector<Disc> seeds_;
  std::vector<Contact> fitted_;
  std::vector<Disc> previous_discs_;  ///< the last frame's fitted contacts, for tracking
  Vector residual_image_;
  CompactOperatorScratch operator_scratch_;
  const std::vector<Contact>& fit_contacts(const std::vector<Contact>& linear);
  const std::vector<Contact>& report_fitted();
};

/// The mean of several frames (the reference is captured as an average). \throw InvalidInput
/// if there are none or their sizes differ.
Frame average_frames(const std::vector<Frame>& frames);

}  // namespace emit
