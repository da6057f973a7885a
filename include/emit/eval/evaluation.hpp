#pragma once
/// \file evaluation.hpp
/// The yardstick (paper §3.2; docs/physics.md, "How it is checked"): frames from the twin on a finer, different mesh
/// with the ADC on, reconstructed, and compared with the presses that made them.
#include <cstdint>
#include <vector>

#include "emit/calibrate/pressure_calibration.hpp"
#include "emit/eval/error_stats.hpp"
#include "emit/frame/reconstructor.hpp"
#include "emit/twin/twin.hpp"

namespace emit {

/// Frames of a press sequence, with the no-contact reference the reconstruction subtracts.
struct SimulatedRun {
  PressSequence presses;
  std::vector<Frame> frames;
  Reference reference;  ///< the robust mean of `reference_frames` no-contact frames
};

SimulatedRun simulate_run(Twin& twin, const PressSequence& presses, int reference_frames = 10);

/// The paper's position estimate for a single press: the centroid of every element above the
/// threshold, weighted by area × δφ, seen from +z, and the sheet's point above it (NaN when no
/// element is). Call after Reconstructor::process().
Vector3 thresholded_centroid(const Reconstructor& reconstructor, double threshold_fraction);
/// The same for any image on `mesh` (#F values), e.g. a current-injection skin's.
Vector3 thresholded_centroid(const Mesh& mesh, const Shape& surface, const Vector& image, double threshold_fraction);

struct LocalisationResult {
  ErrorStats image_centroid;     ///< the paper's estimate (thresholded_centroid)
  ErrorStats strongest_contact;  ///< the contact with the largest force
};

/// Single-press frames only.
LocalisationResult localisation_errors(Reconstructor& reconstructor, const SimulatedRun& run,
                                       double threshold_fraction);

/// Fit eq. 8 on the calibration run, then report |P̂ − P| on the test run (both single presses).
struct PressureResult {
  PressureFit fit;
  ErrorStats error_N_per_mm2;  ///< on the test presses
};
PressureResult pressure_errors(Reconstructor& reconstructor, const SimulatedRun& calibration_run,
                               const SimulatedRun& test_run, double threshold_fraction);

/// Two-press frames: the fraction that come out as (at least) two contacts, and the fraction
/// where each press has a contact within `match_mm` of it.
struct TwoPressResult {
  double two_contacts = 0, both_matched = 0;
  int frames = 0;
};
TwoPressResult two_press_rates(Reconstructor& reconstructor, const SimulatedRun& run, double match_mm);

/// Frames of several presses (three, four fingers): the fraction where every press has a contact
/// within `match_mm` of it.
double every_press_found_rate(Reconstructor& reconstructor, const SimulatedRun& run, double match_mm);

/// Single-press frames: the fraction that report more than one contact (false regions).
double extra_contact_rate(Reconstructor& reconstructor, const SimulatedRun& run);

/// One point of the L-curve (Hansen): for an operator R, the mean over the run's frames of the
/// data misfit ‖J·δφ − δV‖ and of the image norm ‖δφ‖, δφ = R·δV.
struct LCurvePoint {
  double residual_norm_V = 0, solution_norm_V = 0;
};
LCurvePoint l_curve_point(const Matrix& J, const CompactOperator& op, const MeasurementSet& measurements,
                          const SimulatedRun& run);

}  // namespace emit
