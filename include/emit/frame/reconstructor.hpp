#pragma once
/// \file reconstructor.hpp
/// The online half (docs/architecture.md, the online line): per frame, δV = V − V_ref → δφ = R·δV → threshold →
/// pressure (eq. 8) → contacts, their force from the image's integral when the calibration has a
/// force law (frame/image_forces.hpp). It allocates nothing per frame: every buffer is sized at
/// construction.
#include <cstdint>
#include <optional>
#include <variant>
#include <vector>

#include "emit/frame/contact_fitter.hpp"
#include "emit/frame/contacts.hpp"
#include "emit/frame/image_forces.hpp"
#include "emit/frame/masked_readings.hpp"
#include "emit/frame/reference.hpp"
#include "emit/frame/shape_refiner.hpp"
#include "emit/model/calibration.hpp"
#include "emit/model/reconstruction_model.hpp"

namespace emit {

struct FrameOptions {
  double threshold_fraction = 0.5;  ///< of the image's maximum (paper §2.4)
  double min_contact_area_mm2 = 0;  ///< smaller regions are dropped
  /// And regions smaller than this many of the image's resolution cells, sheet area / M: M
  /// readings resolve no finer, and what is finer is the electrode ends' single-element spikes
  /// (the Jacobian's edge singularity), 0.1–2 mm² where a press's region is hundreds.
  double min_contact_cells = 1.0;
  /// With a fitter: start each frame from the last frame's contacts (ContactFitter::track), and
  /// seed afresh from the linear image only when that does not explain the frame. A stream of
  /// frames from a moving finger then costs a fraction of a cold fit; frames that are not a stream
  /// cost one tracking attempt more. While tracking holds, the linear image is not computed.
  bool track_contacts = true;
  /// A contact is reported only where the image stands out from its noise: some element of the
  /// region above k·σ_k, σ_k = σ(δV)·‖row k of R‖ (model/image_noise.hpp), k chosen so that a
  /// frame of pure noise reports a contact with at most this probability. 0: no such test (nor
  /// without the model's reading noise).
  double false_alarm_rate = 0.01;
  /// With a fitter: each fitted contact refitted as an ellipse (shape_refiner.hpp; on a curved sheet
  /// in the tangent plane at its centre),
  /// so it is reported with its outline's area, elongation and orientation, its force from them,
  /// and drawn as that ellipse in pressure(). Off: the disc fit's contacts with the calibration
  /// indenter's area. The `shapes` method sets it (pipeline/pipeline.hpp).
  bool contact_shapes = false;
  /// A declared indenter (contact fitting, `--contact-radius-mm`): a user who knows what presses
  /// (a 3 mm stylus, a 10 mm finger pad) states its radius R [mm], and every contact's area is
  /// held at π R² with the small σ below instead of the calibration indenter's with the prior's
  /// σ of radii 2–10 mm (shape_refiner.hpp); its pressure and force follow from that area. 0: not
  /// declared.
  double contact_radius_mm = 0;
  /// The declared radius' σ of log r: 5 %, a stated indenter's tolerance (a finger pad's contact
  /// grows with its force by more; declare its typical radius).
  double contact_radius_log_std = 0.05;
  void validate() const;  ///< \throw InvalidInput naming the option (core/option_check.hpp)
};

class Reconstructor {
 public:
  /// A linear method: eq. 7 by the model's operator, the threshold, eq. 8 by `calibration`, the
  /// contacts. With the calibration's force law, each contact's force from the image's integral,
  /// its area the calibration indenter's (frame/image_forces.hpp); without, its force Σ P_k A_k
  /// and area over its 50 % region, the image's. Keeps a reference to `model`, which must outlive
  /// it. \throw InvalidInput for a bad option or force law.
  Reconstructor(const ReconstructionModel& model, LinearCalibration calibration, FrameOptions options = {});
  /// Contact fitting (contact_fitter.hpp), seeded by the linear image's contacts (strongest first,
  /// by the model's uncalibrated eq. 8: only their order matters). Contacts are reported with
  /// the calibration's indenter area. `fit`, built with the calibration's contact law and sheet
  /// (pipeline/pipeline.hpp does both) and on the model's measurements, must outlive this; the
  /// reconstructor fits with a ContactFitter of its own on it, so reconstructors on one `fit` may
  /// run on several threads at once. \throw InvalidInput for a bad option.
  Reconstructor(const ReconstructionModel& model, const FitPrecompute& fit, const FitCalibration& calibration,
                FrameOptions options = {});

  /// The no-contact reference (frame/reference.hpp); how many frames' noise it holds sets the
  /// significance floor (its noise adds to every δV: model/image_noise.hpp). A value that is not
  /// finite (a reading no reference frame held) masks its reading in every frame.
  /// \throw InvalidInput if its frame is not N×N or has no finite value, or its count is below 1.
  void set_reference(const Reference& reference);

  /// The last frame's fit (null for a linear method).
  const FitResult* fit_result() const { return fitter_ ? &fitter_result_ : nullptr; }

  /// One frame → contacts (valid until the next call). Readings not finite or clipped at the ADC's
  /// top code (ReconstructionModel::clipped_at_V) are masked: filled by their mean given the others
  /// (frame/masked_readings.hpp), so the image is the one the other readings give. A frame with
  /// more than half its readings masked tells nothing: no contacts. \throw InvalidInput if the
  /// frame is not N×N.
  const std::vector<Contact>& process(const FrameView& frame);
  const std::vector<Contact>& process(const Frame& frame) { return process(frame_view(frame)); }

  /// The last frame's masked readings (their indices in the model's measurement set).
  const std::vector<Index>& masked_readings() const { return masked_; }
  const Vector& image() const { return dphi_; }         ///< δφ per element [V] (0 while tracking holds)
  const Vector& pressure() const { return pressure_; }  ///< per element [N/mm²], 0 below threshold
  /// Per element, the image value a contact must exceed somewhere (−∞ without the test).
  const Vector& significance_floor() const { return floor_; }
  const Mesh& mesh() const { return model_.mesh; }
  const Shape& surface() const { return model_.surface; }

 private:
  const ReconstructionModel& model_;
  /// Eq. 8 on the linear image: the calibration of a linear method, the model's uncalibrated one
  /// for contact fitting's seeds.
  LinearCalibration linear_;
  double indenter_radius_mm_ = 0;  ///< contact fitting's (FitCalibration::indenter_radius_mm)
  double gamma_ = -1.2;            ///< contact fitting's contact law's exponent (for the force's σ)
  FrameOptions options_;
  double min_area_mm2_ = 0;  ///< the larger of min_contact_area_mm2 and min_contact_cells' area
  ContactFinder finder_;
  std::optional<ImageForces> image_forces_;  ///< with linear_.force_law
  Vector reference_, dV_, dphi_, pressure_;
  std::vector<Index> masked_;  ///< capacity M, kept
  MaskedReadingFill fill_;
  Vector noise_per_volt_;  ///< ‖row k of R‖ times the significance's k
  Vector floor_;
  std::vector<std::uint8_t> selected_;
  std::optional<ContactFitter> fitter_;
  std::optional<ShapeRefiner> shapes_;
  ContactLaw law_;  ///< contact fitting's (its calibration's)
  FitResult fitter_result_;
  std::vector<Disc> seeds_;
  std::vector<Contact> fitted_;
  std::vector<Disc> previous_discs_;  ///< the last frame's fitted contacts, for tracking
  Vector residual_image_;
  CompactOperatorScratch operator_scratch_;
  const std::vector<Contact>& fit_contacts(const std::vector<Contact>& linear);
  const std::vector<Contact>& report_fitted();
  void report_shapes(const std::vector<RefinedContact>& shapes);
};

}  // namespace emit
