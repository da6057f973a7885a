#include "emit/eval/real_evaluation.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <string>

#include "emit/core/errors.hpp"
#include "emit/eval/evaluation.hpp"
#include "emit/mesh/generate_mesh.hpp"
#include "emit/model/conductivity_jacobian.hpp"
#include "emit/model/reconstruction_operator.hpp"

namespace emit {

void RealEvalOptions::validate(Index presses, const std::string& folder) const {
  fit.validate();
  // The calibration's cross-validation takes 2 presses a fold at least; one press at least is held out.
  const Index least = 2 * static_cast<Index>(fit.folds);
  const auto held_from = [&](Index n) { return test_from < 0 ? n - n / 5 : test_from; };
  Index needed = least + 1;
  while (test_from < 0 && (needed / 5 < 1 || held_from(needed) < least)) ++needed;
  const std::string folds = " (2 per fold of its " + std::to_string(fit.folds) + "-fold cross-validation)";
  if (presses < needed)
    throw InvalidInput(folder + ": " + std::to_string(presses) + " presses, too few: calibration takes at least " +
                       std::to_string(least) + folds + " and the held-out presses" +
                       (test_from < 0 ? " (the last fifth)" : "") + " 1 or more; the folder needs " +
                       std::to_string(needed) + " presses or more");
  if (test_from >= 0 && (test_from < least || test_from >= presses))
    throw InvalidInput("--test-from: must be between " + std::to_string(least) + ", the least calibration takes" +
                       folds + ", and " + std::to_string(presses - 1) + " (" + folder + "'s presses less one), got " +
                       std::to_string(test_from));
  const Index held = held_from(presses);
  if (calibration_presses < least || calibration_presses > held)
    throw InvalidInput("--calibration-presses: must be between " + std::to_string(least) + " and " +
                       std::to_string(held) + " (the presses before the held-out ones), got " +
                       std::to_string(calibration_presses));
  if (grid_divisions < 2) throw InvalidInput("grid divisions: must be at least 2");
}

namespace {

/// The normalised changes of presses [first, last) as rows (NaN where masked), and their
/// centres; presses with no change that can be used are left out and listed in `unusable`.
void changes_of(const RealDataset& data, const ReadingScreen& screen, Index first, Index last, Matrix& changes,
                std::vector<Vector2>& positions, std::vector<Index>* unusable) {
  changes.resize(last - first, data.readings());
  positions.clear();
  Vector change(data.readings());
  Index rows = 0;
  for (Index i = first; i < last; ++i) {
    if (!(relative_change(data.frames.row(i).transpose(), data.references.row(i).transpose(), change, screen) > 0)) {
      if (unusable) unusable->push_back(i);
      continue;
    }
    changes.row(rows++) = change.transpose();
    positions.push_back(data.contacts[static_cast<std::size_t>(i)].front());
  }
  changes.conservativeResize(rows, Eigen::NoChange);
}

/// Locate presses from..end with `locator`; the errors of those from test_from on.
ErrorStats held_out_errors(const RealDataset& data, PressLocator& locator, Index test_from,
                           std::vector<LocatedPress>* located, Index from) {
  std::vector<double> errors;
  int missed = 0;
  for (Index i = from; i < data.presses(); ++i) {
    const LocatedPress p = locator.locate(data.frames.row(i).transpose(), data.references.row(i).transpose());
    if (located) located->push_back(p);
    if (i < test_from) continue;
    if (p.found) errors.push_back((p.position_mm - data.contacts[static_cast<std::size_t>(i)].front()).norm());
    else ++missed;
  }
  return summarize_errors(errors, missed);
}

/// The held-out presses located by the difference image alone (RealEvalOptions::image).
ErrorStats image_errors(const RealDataset& data, const Sensor& sensor, const ReadingScreen& screen, Index test_from,
                        long& triangles, const Progress& progress) {
  progress.say("the physics alone: meshing, the relative conductivity Jacobian, the NOSER operator");
  const Mesh mesh = generate_mesh(sensor, reconstruction_mesh_options(sensor));
  triangles = static_cast<long>(mesh.triangle_count());
  OperatorOptions noser;
  noser.prior = Prior::noser;
  const CompactOperator op = build_compact_operator(relative_conductivity_jacobian(mesh, sensor), mesh, noser);
  CompactOperatorScratch scratch = op.scratch();
  Vector change(data.readings()), image(op.rows());
  std::vector<double> errors;
  int missed = 0;
  for (Index i = test_from; i < data.presses(); ++i) {
    // A masked reading or a dropped channel reads as no change: the image is linear.
    bool any = false;
    for (Index m = 0; m < change.size(); ++m) {
      const double v = data.frames(i, m), ref = data.references(i, m);
      const bool used = !screen.is_dropped(m) && screen.usable(v, ref);
      change(m) = used ? std::log(v / ref) : 0;
      any = any || used;
    }
    if (!any) {
      ++missed;
      continue;
    }
    op.apply(change, image, scratch);
    // A press may raise or lower the conductance: the paper's estimator on the image's stronger sign.
    if (image.maxCoeff() < -image.minCoeff()) image = -image;
    const Vector3 centre = thresholded_centroid(mesh, sensor.shape, image, 0.5);
    if (centre.allFinite())
      errors.push_back((centre.head<2>() - data.contacts[static_cast<std::size_t>(i)].front()).norm());
    else ++missed;  // an image of zeros: the change lies in the operator's kernel
  }
  return summarize_errors(errors, missed);
}

}  // namespace

RealEvaluation evaluate_real(const RealDataset& data, const Sensor& sensor, const RealEvalOptions& options,
                             const Progress& progress) {
  options.validate(data.presses(), data.folder);
  if (!sensor.excitation)
    throw InvalidInput("the sensor has no \"excitation\": emit eval --real needs a current-injection skin's protocol");
  const auto M = static_cast<Index>(sensor.excitation->readings.size());
  if (data.readings() != M)
    throw InvalidInput(data.folder + "/frames.csv: " + std::to_string(data.readings()) +
                       " values a frame, the sensor's " + "excitation reads " + std::to_string(M));
  for (Index i = 0; i < data.presses(); ++i)
    if (data.contacts[static_cast<std::size_t>(i)].size() != 1)
      throw InvalidInput(data.folder + "/truth.csv: frame " + std::to_string(i) + " has " +
                         std::to_string(data.contacts[static_cast<std::size_t>(i)].size()) +
                         " presses; emit eval --real takes single presses");
  RealEvaluation e;
  e.presses = data.presses();
  e.readings = M;
  e.test_from = options.test_from < 0 ? data.presses() - data.presses() / 5 : options.test_from;
  e.calibration_presses = options.calibration_presses;

  progress.say("surveying the readings");
  e.survey = survey_readings(data.frames, data.references, options.readings);
  PressLocatorOptions locating{options.grid_divisions, 0, e.survey.screen, -1};
  Matrix changes;
  std::vector<Vector2> positions;
  // The curve, then the calibration asked for (its contacts written, its time measured).
  for (const Index n : options.curve) {
    if (n < 2 * static_cast<Index>(options.fit.folds) || n > e.test_from || n == options.calibration_presses) continue;
    progress.say("the curve: calibrating on the first " + std::to_string(n) + " presses");
    changes_of(data, e.survey.screen, 0, n, changes, positions, nullptr);
    const PressResponseFit fit = fit_press_response(changes, positions, options.fit);
    locating.drift_rate = fit.drift_rate;
    PressLocator locator(fit.response, locating);
    e.curve.push_back({n, held_out_errors(data, locator, e.test_from, nullptr, n), fit.kept});
  }
  progress.say("calibrating on the first " + std::to_string(e.calibration_presses) + " presses");
  changes_of(data, e.survey.screen, 0, e.calibration_presses, changes, positions, &e.unusable_calibration_presses);
  e.fit = fit_press_response(changes, positions, options.fit, progress);
  locating.drift_rate = e.fit.drift_rate;
  PressLocator locator(e.fit.response, locating);
  progress.say("locating presses " + std::to_string(e.calibration_presses) + " to " + std::to_string(e.presses - 1));
  const auto start = std::chrono::steady_clock::now();
  e.held_out = held_out_errors(data, locator, e.test_from, &e.located, e.calibration_presses);
  const std::chrono::duration<double, std::milli> elapsed = std::chrono::steady_clock::now() - start;
  e.ms_per_frame = elapsed.count() / static_cast<double>(e.presses - e.calibration_presses);
  e.curve.push_back({e.calibration_presses, e.held_out, e.fit.kept});
  Index found = 0;
  for (Index i = std::max(e.test_from, e.calibration_presses); i < e.presses; ++i) {
    const LocatedPress& p = e.located[static_cast<std::size_t>(i - e.calibration_presses)];
    if (!p.found) continue;
    const double error = (p.position_mm - data.contacts[static_cast<std::size_t>(i)].front()).norm();
    ++found;
    e.within_1sigma += error <= p.std_mm ? 1 : 0;
    e.within_2sigma += error <= 2 * p.std_mm ? 1 : 0;
    e.held_out_sigma_mm += p.std_mm;
  }
  if (found > 0)
    for (double* x : {&e.within_1sigma, &e.within_2sigma, &e.held_out_sigma_mm}) *x /= static_cast<double>(found);
  std::sort(e.curve.begin(), e.curve.end(),
            [](const auto& a, const auto& b) { return a.calibration_presses < b.calibration_presses; });
  std::vector<double> centre;
  for (Index i = e.test_from; i < e.presses; ++i)
    centre.push_back((data.contacts[static_cast<std::size_t>(i)].front() - e.fit.response.center_mm).norm());
  e.held_out_centre = summarize_errors(centre, 0);
  if (options.image)
    e.held_out_image = image_errors(data, sensor, e.survey.screen, e.test_from, e.image_triangles, progress);
  return e;
}

}  // namespace emit
