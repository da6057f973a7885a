#include "emit/eval/tracking_evaluation.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <limits>
#include <numbers>
#include <random>
#include <string>

#include "emit/core/errors.hpp"
#include "emit/core/option_check.hpp"
#include "emit/pipeline/pipeline.hpp"
#include "emit/sensor/surface.hpp"
#include "emit/twin/adc_noise.hpp"
#include "emit/twin/press_scripts.hpp"
#include "emit/twin/twin.hpp"

namespace emit {

namespace {

/// A finger is found when a contact is within this of its press's centre [mm] (a fit's error is
/// tenths of a millimetre; two fingers are 12 mm or more apart).
constexpr double found_within_mm = 5;

double seconds_since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

/// Indices of the contacts that are the two fingers (the pair of least total distance, each within
/// found_within_mm), −1 where a finger has none.
std::pair<int, int> find_fingers(const Shape& surface, const std::vector<Contact>& contacts, const Vector2& a,
                                 const Vector2& b) {
  std::pair<int, int> best{-1, -1};
  double best_total = std::numeric_limits<double>::infinity();
  const int n = static_cast<int>(contacts.size());
  for (int i = -1; i < n; ++i)
    for (int j = -1; j < n; ++j) {
      if (i == j && i >= 0) continue;
      double total = 0;  // an unfound finger costs found_within_mm
      for (const auto& [k, truth] : {std::pair{i, a}, std::pair{j, b}}) {
        double d = found_within_mm;
        if (k >= 0) d = (chart_of(surface, contacts[static_cast<std::size_t>(k)]) - truth).norm();
        if (d > found_within_mm) d = std::numeric_limits<double>::infinity();
        total += d;
      }
      if (total < best_total) best_total = total, best = {i, j};
    }
  return best;
}

/// One tracker's record of one crossing.
struct CrossingRecord {
  std::int64_t first[2] = {-1, -1};
  bool swapped = false, broken = false;
  int downs = 0, ups = 0;
  void see(int finger, std::int64_t id) {
    if (first[finger] < 0) first[finger] = id;
    else if (id == first[1 - finger]) swapped = true;
    else if (id != first[finger]) broken = true;
  }
};

/// RMS distance about the mean of chart points.
double rms_about_mean(const std::vector<Vector2>& points) {
  Vector2 mean = Vector2::Zero();
  for (const Vector2& p : points) mean += p;
  mean /= static_cast<double>(points.size());
  double sum2 = 0;
  for (const Vector2& p : points) sum2 += (p - mean).squaredNorm();
  return std::sqrt(sum2 / static_cast<double>(points.size()));
}

}  // namespace

void TrackingEvalOptions::validate() const {
  option_check::at_least("TrackingEvalOptions", "crossings", crossings, 1);
  option_check::at_least("TrackingEvalOptions", "min_frames", min_frames, 2);
  option_check::at_least("TrackingEvalOptions", "max_frames", max_frames, min_frames);
  option_check::positive("TrackingEvalOptions", "min_separation_mm", min_separation_mm);
  option_check::at_least("TrackingEvalOptions", "still_frames", still_frames, 10);
  option_check::positive("TrackingEvalOptions", "frames_per_s", frames_per_s);
  option_check::positive("TrackingEvalOptions", "still_force_N", still_force_N);
  if (max_separation_mm < min_separation_mm || max_force_N < min_force_N || !(min_force_N > 0))
    throw InvalidInput("TrackingEvalOptions: the separations and forces must be ranges MIN <= MAX, forces positive");
  tracker.validate();
}

TrackingEvalOptions quick_tracking_options() {
  TrackingEvalOptions options;
  options.crossings = 4;
  options.still_frames = 40;
  return options;
}

TrackingEvaluation evaluate_tracking(const EvalCase& eval_case, const TrackingEvalOptions& options,
                                     const Progress& progress) {
  options.validate();
  const Sensor& sensor = eval_case.sensor;
  const Shape& surface = sensor.shape;
  progress.say("meshing the twin (mesh seed " + std::to_string(options.mesh_seed) + ")");
  TwinOptions twin_options;
  twin_options.mesh_seed = options.mesh_seed;
  twin_options.noise_seed = options.seed;
  Twin twin(sensor, twin_options);
  std::vector<Frame> untouched;
  untouched.reserve(10);
  for (int i = 0; i < 10; ++i) untouched.push_back(twin.frame({}));
  const Reference reference = average_reference(untouched);
  PipelineOptions pipeline_options;
  pipeline_options.method = Method::fit;
  const Pipeline pipeline(sensor, pipeline_options, {}, progress.stage);
  const double frame_s = 1 / options.frames_per_s;

  TrackingEvaluation result;
  double reconstruct_s = 0, track_s = 0;
  long reconstructed = 0, tracked = 0;
  TrackerOptions tracker_options[2] = {options.tracker, options.tracker};
  tracker_options[0].filter = false, tracker_options[1].filter = true;
  std::mt19937_64 draw(options.seed);
  for (int trial = 0; trial < options.crossings; ++trial) {
    progress.step("crossing", trial, options.crossings);
    const int frames = std::uniform_int_distribution<int>(options.min_frames, options.max_frames)(draw);
    PressStyle style;
    style.min_force_N = options.min_force_N, style.max_force_N = options.max_force_N;
    style.seed = options.seed + 1 + static_cast<std::uint64_t>(trial);
    const PressSequence script =
        crossing_script(sensor, frames, options.min_separation_mm, options.max_separation_mm, style);
    Reconstructor reconstructor = pipeline.reconstructor();
    reconstructor.set_reference(reference);
    ContactTracker trackers[2] = {ContactTracker(tracker_options[0], 64, surface),
                                  ContactTracker(tracker_options[1], 64, surface)};
    CrossingRecord records[2];
    for (int f = 0; f < frames; ++f) {
      const std::vector<Press>& presses = script[static_cast<std::size_t>(f)];
      const Frame frame = twin.frame(presses);
      auto start = std::chrono::steady_clock::now();
      const std::vector<Contact>& contacts = reconstructor.process(frame);
      reconstruct_s += seconds_since(start), ++reconstructed;
      const auto [i, j] =
          find_fingers(surface, contacts, press_chart_mm(surface, presses[0]), press_chart_mm(surface, presses[1]));
      result.frames_missing_a_finger += (i < 0) + (j < 0);
      ++result.crossing_frames;
      for (int k = 0; k < 2; ++k) {
        start = std::chrono::steady_clock::now();
        const std::vector<Contact>& out = trackers[k].update(contacts, f * frame_s);
        track_s += seconds_since(start), ++tracked;
        for (const Contact& c : out) records[k].downs += c.phase == TouchPhase::down;
        records[k].ups += static_cast<int>(trackers[k].ended().size());
        if (i >= 0) records[k].see(0, out[static_cast<std::size_t>(i)].id);
        if (j >= 0) records[k].see(1, out[static_cast<std::size_t>(j)].id);
      }
    }
    for (int k = 0; k < 2; ++k) {
      for (int f = 0; f <= options.tracker.coast_frames; ++f) {  // lift both: every touch ends
        trackers[k].update({}, (frames + f) * frame_s);
        records[k].ups += static_cast<int>(trackers[k].ended().size());
      }
      CrossingScore& score = k == 0 ? result.unfiltered : result.filtered;
      ++score.trials;
      score.swapped += records[k].swapped;
      score.broken += records[k].broken;
      score.right_events += records[k].downs == 2 && records[k].ups == 2;
    }
  }
  progress.step("crossing", options.crossings, options.crossings);

  // A press held still, then steps: the noise-free frames once, the ADC's noise drawn per frame.
  PressStyle style;
  style.min_force_N = style.max_force_N = options.still_force_N;
  style.seed = options.seed;
  const Press still = random_script(sensor, 1, style)[0][0];
  const Vector2 place = press_chart_mm(surface, still);
  std::mt19937_64 noise(options.seed + 1000003);
  const auto noisy = [&](const Frame& exact) {
    Frame f = exact;
    apply_adc(sensor.adc, f, noise);
    return f;
  };
  char what[64];
  std::snprintf(what, sizeof what, "a %g N press held still, and steps", options.still_force_N);
  progress.say(what);
  const Frame still_exact = twin.exact_frame({still});
  for (const double step_mm : {0.0, 0.5, 3.0}) {
    Vector2 to = place;
    Frame step_exact;
    if (step_mm > 0) {
      bool found = false;
      for (int attempt = 0; attempt < 64 && !found; ++attempt) {
        const double angle = 2 * std::numbers::pi * attempt / 64;
        to = place + step_mm * Vector2(std::cos(angle), std::sin(angle));
        try {
          moving_script(sensor, 2, place, to, style);  // both ends inside the margin
          found = true;
        } catch (const InvalidInput&) {
        }
      }
      if (!found) throw InvalidInput("tracking evaluation: no room for a step from the still press");
      step_exact = twin.exact_frame({press_at_chart(surface, to, style.radius_mm, options.still_force_N)});
    }
    Reconstructor reconstructor = pipeline.reconstructor();
    reconstructor.set_reference(reference);
    ContactTracker trackers[2] = {ContactTracker(tracker_options[0], 64, surface),
                                  ContactTracker(tracker_options[1], 64, surface)};
    std::vector<Vector2> places[2];
    const int before = step_mm > 0 ? options.still_frames / 2 : options.still_frames;
    const int total = step_mm > 0 ? 2 * before : before;
    for (int f = 0; f < total; ++f) {
      const auto start = std::chrono::steady_clock::now();
      const std::vector<Contact>& contacts = reconstructor.process(noisy(f < before ? still_exact : step_exact));
      reconstruct_s += seconds_since(start), ++reconstructed;
      for (int k = 0; k < 2; ++k) {
        const std::vector<Contact>& out = trackers[k].update(contacts, f * frame_s);
        // The touch of the first contact (the only one expected); its place, or the last one's.
        const Contact* c = out.empty() ? nullptr : &out[0];
        places[k].push_back(c ? chart_of(surface, *c) : places[k].empty() ? place : places[k].back());
      }
    }
    if (step_mm == 0) {
      // After the filter's settling (10 frames).
      result.jitter_mm = rms_about_mean({places[0].begin() + 10, places[0].end()});
      result.filtered_jitter_mm = rms_about_mean({places[1].begin() + 10, places[1].end()});
      continue;
    }
    Vector2 settled = Vector2::Zero();  // the new place as the unfiltered contacts put it
    for (int f = before; f < total; ++f) settled += places[0][static_cast<std::size_t>(f)];
    settled /= total - before;
    StepLag lag{step_mm, -1, -1};
    for (int k = 0; k < 2; ++k) {
      int& frames = k == 0 ? lag.raw_lag_frames : lag.lag_frames;
      for (int f = before; f < total && frames < 0; ++f)
        if ((places[k][static_cast<std::size_t>(f)] - settled).norm() <= 0.1 * step_mm) frames = f - before;
    }
    result.steps.push_back(lag);
  }
  result.reconstruct_ms_per_frame = reconstructed > 0 ? 1e3 * reconstruct_s / static_cast<double>(reconstructed) : 0;
  result.track_us_per_frame = tracked > 0 ? 1e6 * track_s / static_cast<double>(tracked) : 0;
  return result;
}

}  // namespace emit
