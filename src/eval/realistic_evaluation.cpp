#include "emit/eval/realistic_evaluation.hpp"

#include <array>
#include <chrono>
#include <cstdio>
#include <limits>
#include <optional>
#include <variant>

#include "emit/calibrate/sensor_calibration.hpp"
#include "emit/core/errors.hpp"
#include "emit/model/fit_model.hpp"
#include "emit/pipeline/pipeline.hpp"
#include "emit/pipeline/press_calibration.hpp"
#include "emit/twin/press_scripts.hpp"
#include "emit/twin/twin.hpp"

namespace emit {

RealisticEvalCounts quick_realistic_counts() {
  RealisticEvalCounts counts;
  // Not fewer calibration presses: the calibration's cost is its Green's functions, not its
  // presses, and on fewer it converges more slowly (on seed 3, 12 presses ran all 20 iterations
  // where 40 stop after 3); its first two iterations bring the misfit from 43 mV to 1.2 mV rms.
  counts.calibration_presses = 40;
  counts.calibration_iterations = 2;
  // The slow frames are few: with the nominal file a fit takes ~2 s a frame, and a cold fit of
  // three or four presses ~5 s (it tries more contacts while the misfit says so).
  counts.test_presses = 3;
  counts.presses_per_indenter = 1;
  counts.multi_press_frames = 1;
  return counts;
}

void RealisticEvalOptions::validate() const {
  const auto at_least = [](int value, int least, const char* name) {
    if (value < least)
      throw InvalidInput(std::string("realistic evaluation: ") + name + " must be " + std::to_string(least) +
                         " or more, got " + std::to_string(value));
  };
  at_least(counts.reference_frames, 1, "reference_frames");
  at_least(counts.calibration_presses, least_calibration_presses, "calibration_presses");
  at_least(counts.test_presses, 1, "test_presses");
  at_least(counts.presses_per_indenter, 1, "presses_per_indenter");
  at_least(counts.multi_press_frames, 1, "multi_press_frames");
  at_least(counts.calibration_iterations, 0, "calibration_iterations");
  if (unplaced_known_forces != 0 && (unplaced_known_forces < 2 || unplaced_known_forces > counts.calibration_presses))
    throw InvalidInput("realistic evaluation: unplaced_known_forces must be 0 or 2 to calibration_presses (" +
                       std::to_string(counts.calibration_presses) + "), got " + std::to_string(unplaced_known_forces));
  sheet.validate();
}

namespace {

using Clock = std::chrono::steady_clock;

double seconds_since(Clock::time_point start) { return std::chrono::duration<double>(Clock::now() - start).count(); }

/// The README's round on the 60 mm sheet: a 5 mm flat indenter, 2–39 N (0.025–0.5 N/mm², the
/// paper's range); several fingers 5–20 N each (as `emit eval`'s two fingers), 12 mm apart.
constexpr double round_radius_mm = 5, round_min_force_N = 2, round_max_force_N = 39;
constexpr double fingers_min_force_N = 5, fingers_max_force_N = 20, fingers_separation_mm = 12;
/// The other indenters' radii on the 60 mm sheet.
constexpr std::array<double, 5> other_radii_mm{3, 4, 6, 8, 10};

/// Presses of radius `radius_mm`, forces scaled from the 5 mm indenter's by `force_scale`, at
/// least a radius from the border (as `emit simulate`'s scripts).
PressStyle style_of(double radius_mm, double min_force_N, double max_force_N, double force_scale, std::uint64_t seed,
                    PressProfile profile = PressProfile::flat) {
  PressStyle style;
  style.radius_mm = radius_mm;
  style.min_force_N = force_scale * min_force_N, style.max_force_N = force_scale * max_force_N;
  style.margin_mm = radius_mm;
  style.seed = seed;
  style.profile = profile;
  return style;
}

/// The realistic sheet's twin with its own noise: one per run, as `emit simulate --seed` makes
/// one per file.
Twin twin_of(const RealisticSheet& sheet, std::uint64_t noise_seed) {
  TwinOptions options = sheet.twin_options;
  options.noise_seed = noise_seed;
  return Twin(sheet.twin_sensor, options);
}

std::vector<Frame> simulate(Twin& twin, const PressSequence& presses, const std::string& what,
                            const Progress& progress) {
  std::vector<Frame> frames;
  frames.reserve(presses.size());
  for (const std::vector<Press>& frame_presses : presses) {
    frames.push_back(twin.frame(frame_presses));
    progress.step("simulating " + what, static_cast<long>(frames.size()), static_cast<long>(presses.size()));
  }
  return frames;
}

/// Each frame's contacts, by a reconstructor of its own (as one `emit reconstruct` per file).
ContactSequence reconstruct(Pipeline& pipeline, const Reference& reference, const std::vector<Frame>& frames,
                            const std::string& what, const Progress& progress) {
  Reconstructor reconstructor = pipeline.reconstructor();
  reconstructor.set_reference(reference);
  ContactSequence contacts;
  contacts.reserve(frames.size());
  for (const Frame& frame : frames) {
    contacts.push_back(reconstructor.process(frame));
    progress.step("reconstructing " + what, static_cast<long>(contacts.size()), static_cast<long>(frames.size()));
  }
  return contacts;
}

/// Every frame the round simulates, with its presses.
struct RealisticRuns {
  Reference reference;
  PressSequence calibration, test, three, four;
  std::vector<PressSequence> indenters;  ///< per IndenterScore, in its order
  std::vector<Frame> calibration_frames, test_frames, three_frames, four_frames;
  std::vector<std::vector<Frame>> indenter_frames;
};

RealisticRuns simulate_round(const EvalCase& c, const RealisticSheet& sheet, const RealisticEvalOptions& options,
                             std::vector<IndenterScore>& indenters, const Progress& progress) {
  const RealisticEvalCounts& n = options.counts;
  const double scale = c.radius_mm / round_radius_mm, force_scale = scale * scale;
  const std::uint64_t seed = options.seed;
  RealisticRuns runs;
  {
    progress.say("meshing the realistic sheet's twin (reference, seed " + std::to_string(seed) + ")");
    Twin twin = twin_of(sheet, seed);
    runs.reference = average_reference(
        simulate(twin, PressSequence(static_cast<std::size_t>(n.reference_frames)), "reference frame", progress));
  }
  {
    progress.say("meshing the twin (calibration presses, seed " + std::to_string(seed + 1) + ")");
    Twin twin = twin_of(sheet, seed + 1);
    runs.calibration =
        random_script(c.sensor, n.calibration_presses,
                      style_of(c.radius_mm, round_min_force_N, round_max_force_N, force_scale, seed + 1));
    runs.calibration_frames = simulate(twin, runs.calibration, "calibration press", progress);
  }
  {
    progress.say("meshing the twin (test presses, seed " + std::to_string(seed + 2) + ")");
    Twin twin = twin_of(sheet, seed + 2);
    runs.test = random_script(c.sensor, n.test_presses,
                              style_of(c.radius_mm, round_min_force_N, round_max_force_N, force_scale, seed + 2));
    runs.test_frames = simulate(twin, runs.test, "test press", progress);
  }
  progress.say("meshing the twin (other indenters and several fingers, seed " + std::to_string(seed + 3) + ")");
  Twin twin = twin_of(sheet, seed + 3);
  std::uint64_t script_seed = seed + 3;
  for (const PressProfile profile : {PressProfile::flat, PressProfile::spherical})
    for (const double radius_mm : other_radii_mm) {
      const double r = scale * radius_mm;
      indenters.push_back({r, profile, {}});
      runs.indenters.push_back(
          random_script(c.sensor, n.presses_per_indenter,
                        style_of(r, round_min_force_N, round_max_force_N, force_scale, script_seed++, profile)));
      char what[64];
      std::snprintf(what, sizeof what, "%s %g mm press", profile_name(profile), r);
      runs.indenter_frames.push_back(simulate(twin, runs.indenters.back(), what, progress));
    }
  const PressStyle fingers = style_of(c.radius_mm, fingers_min_force_N, fingers_max_force_N, force_scale, script_seed);
  runs.three = fingers_script(c.sensor, n.multi_press_frames, 3, scale * fingers_separation_mm, fingers);
  runs.three_frames = simulate(twin, runs.three, "frame of three presses", progress);
  PressStyle four = fingers;
  four.seed = script_seed + 1;
  runs.four = fingers_script(c.sensor, n.multi_press_frames, 4, scale * fingers_separation_mm, four);
  runs.four_frames = simulate(twin, runs.four, "frame of four presses", progress);
  return runs;
}

/// Step 4: the paper method, calibrated on the calibration presses as `emit calibrate --method
/// paper` does, on the test presses and the other indenters; and with eq. 8 alone.
void evaluate_paper(const EvalCase& c, const RealisticRuns& runs, RealisticEvaluation& result,
                    const Progress& progress) {
  progress.say("the paper method, calibrated as emit calibrate --method paper does");
  PressCalibrationOptions options;
  options.method = Method::paper;
  const PressCalibrationResult calibration =
      calibrate_from_presses(c.sensor, options, runs.reference, runs.calibration_frames, runs.calibration);
  Pipeline paper(c.sensor, PipelineOptions{Method::paper, 0, "", {}}, calibration.calibration, progress.stage);
  result.paper =
      score_single_presses(reconstruct(paper, runs.reference, runs.test_frames, "test press (paper)", progress),
                           runs.test);
  ContactSequence contacts;
  PressSequence presses;
  for (std::size_t k = 0; k < runs.indenters.size(); ++k) {
    const ContactSequence found =
        reconstruct(paper, runs.reference, runs.indenter_frames[k], "other indenter's press (paper)", progress);
    contacts.insert(contacts.end(), found.begin(), found.end());
    presses.insert(presses.end(), runs.indenters[k].begin(), runs.indenters[k].end());
  }
  result.paper_other_indenters = score_single_presses(contacts, presses);
  LinearCalibration equation_8 = std::get<LinearCalibration>(calibration.calibration);
  equation_8.force_law.reset();
  Reconstructor reconstructor(paper.model(), equation_8);
  reconstructor.set_reference(runs.reference);
  contacts.clear();
  for (const Frame& frame : runs.test_frames) contacts.push_back(reconstructor.process(frame));
  result.paper_equation_8 = score_single_presses(contacts, runs.test);
}

}  // namespace

RealisticEvaluation evaluate_realistic_sheet(const EvalCase& eval_case, const RealisticEvalOptions& options,
                                             const Progress& progress) {
  options.validate();
  TwinOptions base;
  base.mesh_seed = options.mesh_seed;  // finer than and different from the reconstruction's mesh
  const RealisticSheet sheet = make_realistic_sheet(eval_case.sensor, options.sheet, base);
  RealisticEvaluation result;
  result.sheet_description = sheet.description;
  result.counts = options.counts;
  result.unplaced_known_forces = options.unplaced_known_forces;
  result.radius_mm = eval_case.radius_mm;
  result.separation_mm = eval_case.radius_mm / round_radius_mm * fingers_separation_mm;
  const RealisticRuns runs = simulate_round(eval_case, sheet, options, result.indenters, progress);

  progress.say("calibrating from " + std::to_string(runs.calibration.size()) + " presses, as emit calibrate does");
  const Clock::time_point calibration_start = Clock::now();
  PressCalibrationOptions calibration_options;  // emit calibrate's defaults
  if (options.counts.calibration_iterations > 0)
    calibration_options.sensor.max_iterations = options.counts.calibration_iterations;
  PressSequence given = runs.calibration;  // what the user knows of the calibration presses
  if (options.unplaced_known_forces > 0)
    for (std::size_t f = 0; f < given.size(); ++f)
      for (Press& press : given[f]) {
        press.x_mm = press.y_mm = std::numeric_limits<double>::quiet_NaN();
        if (f >= static_cast<std::size_t>(options.unplaced_known_forces))
          press.force_N = std::numeric_limits<double>::quiet_NaN();
      }
  const PressCalibrationResult calibration =
      calibrate_from_presses(eval_case.sensor, calibration_options, runs.reference, runs.calibration_frames, given,
                             progress.stage);
  result.calibration_s = seconds_since(calibration_start);
  if (calibration.sheet) {
    result.calibration_warnings = calibration.sheet->warnings;
    result.sheet_parameters =
        parameter_coverage(*calibration.sheet, parameter_truth(*calibration.sheet, sheet, fit_mesh(eval_case.sensor)));
  }

  evaluate_paper(eval_case, runs, result, progress);
  {  // the nominal description, as before calibrating; its models freed before the calibrated ones
    progress.say("contact fitting with the nominal description");
    Pipeline nominal(eval_case.sensor, PipelineOptions{}, std::nullopt, progress.stage);
    result.triangles = static_cast<long>(nominal.model().mesh.triangle_count());
    result.nominal =
        score_single_presses(reconstruct(nominal, runs.reference, runs.test_frames, "test press (nominal)", progress),
                             runs.test);
  }
  progress.say("contact fitting with the calibration");
  Pipeline calibrated(eval_case.sensor, PipelineOptions{}, calibration.calibration, progress.stage);
  const Clock::time_point fit_start = Clock::now();
  result.calibrated = score_single_presses(reconstruct(calibrated, runs.reference, runs.test_frames,
                                                       "test press (calibrated)", progress),
                                           runs.test);
  result.fit_ms_per_frame = 1e3 * seconds_since(fit_start) / static_cast<double>(runs.test_frames.size());

  ContactSequence all_contacts;
  PressSequence all_presses;
  for (std::size_t k = 0; k < result.indenters.size(); ++k) {
    const ContactSequence contacts =
        reconstruct(calibrated, runs.reference, runs.indenter_frames[k], "other indenter's press", progress);
    result.indenters[k].score = score_single_presses(contacts, runs.indenters[k]);
    all_contacts.insert(all_contacts.end(), contacts.begin(), contacts.end());
    all_presses.insert(all_presses.end(), runs.indenters[k].begin(), runs.indenters[k].end());
  }
  result.other_indenters = score_single_presses(all_contacts, all_presses);
  const Clock::time_point several_start = Clock::now();
  result.three_presses = fraction_every_press_matched(reconstruct(calibrated, runs.reference, runs.three_frames,
                                                                  "frame of three presses", progress),
                                                      runs.three, result.match_mm);
  result.four_presses = fraction_every_press_matched(reconstruct(calibrated, runs.reference, runs.four_frames,
                                                                 "frame of four presses", progress),
                                                     runs.four, result.match_mm);
  result.several_ms_per_frame =
      1e3 * seconds_since(several_start) / static_cast<double>(runs.three_frames.size() + runs.four_frames.size());
  result.false_contacts = result.calibrated.extra_contacts + result.other_indenters.extra_contacts;
  result.single_presses = result.calibrated.frames + result.other_indenters.frames;
  return result;
}

}  // namespace emit
