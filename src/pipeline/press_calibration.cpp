#include "emit/pipeline/press_calibration.hpp"

#include <optional>
#include <tuple>

#include "emit/calibrate/contact_law_calibration.hpp"
#include "emit/calibrate/force_calibration.hpp"
#include "emit/calibrate/pressure_calibration.hpp"
#include "emit/core/errors.hpp"
#include "emit/core/option_check.hpp"
#include "emit/frame/image_forces.hpp"
#include "emit/frame/reconstructor.hpp"
#include "emit/mesh/slide_electrodes.hpp"
#include "emit/model/fit_model.hpp"
#include "emit/model/reconstruction_model.hpp"

namespace emit {

namespace {

/// A linear image's integral over the part of the sheet nearest the contact nearest the press
/// (frame/image_forces.hpp); none when the frame shows no contact or that integral is not positive.
std::optional<double> press_integral_V_mm2(ImageForces& image_forces, const Vector& image,
                                           const std::vector<Contact>& contacts, const Press& press) {
  if (contacts.empty()) return std::nullopt;
  const std::vector<double>& integrals = image_forces.integrals(image, contacts);
  std::size_t nearest = 0;
  for (std::size_t j = 1; j < contacts.size(); ++j) {
    const auto distance = [&](const Contact& c) {
      return Vector3(c.x_mm - press.x_mm, c.y_mm - press.y_mm, c.z_mm - press.z_mm).norm();
    };
    if (distance(contacts[j]) < distance(contacts[nearest])) nearest = j;
  }
  if (!(integrals[nearest] > 0)) return std::nullopt;  // the contact's share of the image is noise
  return integrals[nearest];
}

/// Contact fitting's calibration: the sheet (if asked), then the contact law on the corrected sheet.
PressCalibrationResult calibrate_fitting(const Sensor& sensor, const PressCalibrationOptions& options,
                                         const ReconstructionModel& model, const Reference& reference,
                                         const std::vector<Frame>& frames, const PressSequence& truth,
                                         const std::function<void(const std::string&)>& say) {
  std::vector<Frame> weighed;  // the single presses of known force: the contact law's
  std::vector<double> pressures;
  FitCalibration calibration;
  std::size_t single = 0, unplaced = 0;
  for (std::size_t f = 0; f < frames.size(); ++f) {
    if (truth[f].size() != 1) continue;  // calibrate on single presses only
    ++single;
    unplaced += !place_known(truth[f][0]);
    if (!force_known(truth[f][0])) continue;
    calibration.indenter_radius_mm += truth[f][0].radius_mm;
    weighed.push_back(frames[f]);
    pressures.push_back(truth[f][0].pressure_N_per_mm2());
  }
  if (single == 0) throw InvalidInput("calibration: no single presses to calibrate on");
  if (unplaced > 0 && !options.fit_sheet)
    throw InvalidInput("calibration: " + std::to_string(unplaced) +
                       " presses of unknown place; only the sheet's fit places them (leave the sheet's fit on)");
  if (weighed.size() < 2)
    throw InvalidInput("calibration: " + std::to_string(weighed.size()) +
                       " single presses of known force; the contact law (R = alpha P^gamma) needs at least 2, of "
                       "different forces: put a known weight down, or press on a scale");
  calibration.indenter_radius_mm /= static_cast<double>(weighed.size());
  calibration.electrode_count = model.measurements.electrode_count;
  calibration.sensor_name = sensor.name;
  PressCalibrationResult result;
  if (say) say("meshing the sheet for contact fitting");
  FitModel fit_model{fit_mesh(sensor), {}};
  Sensor calibrated = sensor;
  if (options.fit_sheet) {
    result.sheet = calibrate_sensor(sensor, fit_model.mesh, model.measurements, frames, reference.frame, truth,
                                    options.sensor, say);
    calibration.sheet_correction = result.sheet->correction;
    calibration.drive_voltage_V = result.sheet->drive_voltage_V;
    calibration.series_resistance_ohm = result.sheet->series_resistance_ohm;
    calibrated = calibrated_sensor(sensor, *result.sheet);
    if (options.sensor.fit_electrode_positions && sensor.border) {
      calibration.electrode_shift_mm = result.sheet->electrode_shift_mm;
      fit_model.mesh = slide_electrodes(fit_model.mesh, sensor, calibration.electrode_shift_mm);
    }
    std::tie(result.sheet_factor_low, result.sheet_factor_high) = result.sheet->correction.factor_range(fit_model.mesh);
  }
  if (say) say("Green's function (" + std::to_string(fit_model.mesh.node_count()) + " nodes)");
  fit_model.green = fit_green_function(fit_model.mesh, sensor,
                                       calibration.sheet_correction ? &*calibration.sheet_correction : nullptr);
  const FitPrecompute fit(calibrated, fit_model.mesh, fit_model.green, model.measurements);
  FrameOptions frame_options;
  frame_options.threshold_fraction = options.threshold_fraction;
  const FittedLawCalibration fitted =
      calibrate_fitted_contact_law(model, fit, reference, weighed, pressures, sensor.contact, frame_options);
  calibration.contact_law = fitted.law;
  result.calibration = calibration;
  result.presses = fitted.presses;
  result.rms_N_per_mm2 = fitted.rms_N_per_mm2;
  result.max_abs_N_per_mm2 = fitted.max_abs_N_per_mm2;
  return result;
}

}  // namespace

PressCalibrationResult calibrate_linear(const ReconstructionModel& model, double threshold_fraction,
                                        const Reference& reference, const std::vector<Frame>& frames,
                                        const PressSequence& truth) {
  if (truth.size() != frames.size())
    throw InvalidInput("calibration: " + std::to_string(truth.size()) + " frames of presses for " +
                       std::to_string(frames.size()) + " frames");
  FrameOptions frame_options;
  frame_options.threshold_fraction = threshold_fraction;
  Reconstructor reconstructor(model, model.uncalibrated, frame_options);
  reconstructor.set_reference(reference);
  ImageForces image_forces(model.mesh);
  std::vector<PressureSample> samples;
  std::vector<ForceSample> force_samples;
  for (std::size_t f = 0; f < frames.size(); ++f) {
    if (truth[f].size() != 1) continue;  // calibrate on single presses only
    const Press& press = truth[f][0];
    if (!place_known(press) || !force_known(press))
      throw InvalidInput("calibration: frame " + std::to_string(f) +
                         "'s press has no place or no force; the linear methods calibrate on presses of known place "
                         "and force (contact fitting, --method fit, takes the others)");
    const std::vector<Contact>& contacts = reconstructor.process(frames[f]);
    samples.push_back(pressure_sample(reconstructor, threshold_fraction, press.pressure_N_per_mm2()));
    if (const std::optional<double> integral =
            press_integral_V_mm2(image_forces, reconstructor.image(), contacts, press))
      force_samples.push_back({*integral, press.force_N, press.radius_mm});
  }
  const PressureFit fit = fit_pressure_calibration(samples);
  LinearCalibration calibration = fit.calibration;
  const ForceFit force = fit_image_force_law(force_samples);
  calibration.force_law = force.law;
  PressCalibrationResult result;
  result.calibration = calibration;
  result.presses = samples.size();
  result.rms_N_per_mm2 = fit.rms_N_per_mm2;
  result.max_abs_N_per_mm2 = fit.max_abs_N_per_mm2;
  result.force_presses = force_samples.size();
  result.force_error = force.mean_abs_relative_error;
  result.lambda2 = model.options.lambda2;
  return result;
}

PressCalibrationResult calibrate_from_presses(const Sensor& sensor, const PressCalibrationOptions& options,
                                              const Reference& reference, const std::vector<Frame>& frames,
                                              const PressSequence& truth,
                                              const std::function<void(const std::string&)>& progress) {
  options.validate();
  if (truth.size() != frames.size())
    throw InvalidInput("calibration: " + std::to_string(truth.size()) + " frames of presses for " +
                       std::to_string(frames.size()) + " frames");
  OperatorOptions operator_options_ = operator_options(options.method);  // fit: the paper's, its seeds
  if (options.lambda2 > 0) operator_options_.lambda2 = options.lambda2;
  const ReconstructionModel model =
      build_reconstruction_model(sensor, operator_options_, options.cache_dir, {}, progress);
  if (is_linear(options.method)) return calibrate_linear(model, options.threshold_fraction, reference, frames, truth);
  PressCalibrationResult result = calibrate_fitting(sensor, options, model, reference, frames, truth, progress);
  result.lambda2 = model.options.lambda2;  // the λ² chosen, when left to the rule
  return result;
}

void PressCalibrationOptions::validate() const {
  option_check::zero_or_positive("PressCalibrationOptions", "lambda2", lambda2, "the method's");
  if (!(threshold_fraction > 0 && threshold_fraction < 1))
    option_check::fail("PressCalibrationOptions", "threshold_fraction", "a fraction in (0, 1)",
                       std::to_string(threshold_fraction));
  sensor.validate();
}
}  // namespace emit
