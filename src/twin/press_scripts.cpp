#include "emit/twin/press_scripts.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <numbers>
#include <random>
#include <utility>

#include "emit/core/errors.hpp"
#include "emit/core/quote_input.hpp"
#include "emit/sensor/surface.hpp"

namespace emit {

namespace {

Eigen::AlignedBox2d bounding_box(const Border& border) {
  Eigen::AlignedBox2d box;
  for (int k = 0; k < 512; ++k) box.extend(border.point_at(border.length_mm() * k / 512));
  return box;
}

/// Whether chart point p is on the sheet at least margin_mm from its border.
bool admissible(const Shape& shape, const Border& border, const Vector2& p, double margin_mm) {
  return chart_distance_to_border_mm(shape, border, p) >= margin_mm;
}

class Sampler {
 public:
  Sampler(const Sensor& sensor, const PressStyle& style)
      : border_(sheet_outline(sensor)),
        surface_(sensor.shape),
        style_(style),
        box_(bounding_box(border_)),
        rng_(style.seed) {
    if (!(style.radius_mm > 0)) throw InvalidInput("press radius must be positive");
    if (style.min_force_N < 0 || style.max_force_N < style.min_force_N)
      throw InvalidInput("press forces must satisfy 0 <= min <= max");
  }
  double uniform(double a, double b) { return std::uniform_real_distribution<double>(a, b)(rng_); }
  double force() {
    return style_.min_force_N == style_.max_force_N ? style_.min_force_N
                                                    : uniform(style_.min_force_N, style_.max_force_N);
  }
  /// A press centred on the sheet's point named by chart point p (sensor/surface.hpp).
  Press press_at(const Vector2& p) { return press_at_chart(surface_, p, style_.radius_mm, force(), style_.profile); }
  bool admissible(const Vector2& p) const { return emit::admissible(surface_, border_, p, style_.margin_mm); }
  Vector2 random_point() {
    for (int attempt = 0; attempt < 100000; ++attempt) {
      Vector2 p(uniform(box_.min().x(), box_.max().x()), uniform(box_.min().y(), box_.max().y()));
      if (admissible(p)) return p;
    }
    throw InvalidInput("no room for a press " + std::to_string(style_.margin_mm) + " mm from the border");
  }
  const Eigen::AlignedBox2d& box() const { return box_; }

 private:
  const Border& border_;
  const Shape& surface_;
  PressStyle style_;
  Eigen::AlignedBox2d box_;
  std::mt19937_64 rng_;
};

/// The grid's nodes out from the box's centre along x and y: (2 nx + 1)(2 ny + 1) in all.
Vector2 grid_half_counts(const Eigen::AlignedBox2d& box, double spacing_mm) {
  return {std::floor(0.5 * box.sizes().x() / spacing_mm), std::floor(0.5 * box.sizes().y() / spacing_mm)};
}

double grid_node_count(const Vector2& half_counts) { return (2 * half_counts.x() + 1) * (2 * half_counts.y() + 1); }

}  // namespace

PressSequence grid_script(const Sensor& sensor, double spacing_mm, double jitter_mm, const PressStyle& style) {
  if (!(spacing_mm > 0)) throw InvalidInput("grid spacing must be positive");
  Sampler sampler(sensor, style);
  PressSequence frames;
  const auto& box = sampler.box();
  const Vector2 centre = box.center();
  const Vector2 half_counts = grid_half_counts(box, spacing_mm);
  // nx, ny as ints: a guard only, far above a run's own bound (core/limits.hpp, checked by simulate_job).
  if (!(grid_node_count(half_counts) <= std::numeric_limits<int>::max())) {
    char message[96];
    std::snprintf(message, sizeof message, "grid spacing %g mm: more presses than an int counts", spacing_mm);
    throw InvalidInput(message);
  }
  const int nx = static_cast<int>(half_counts.x()), ny = static_cast<int>(half_counts.y());
  for (int j = -ny; j <= ny; ++j)
    for (int i = -nx; i <= nx; ++i) {
      const Vector2 node = centre + spacing_mm * Vector2(i, j);
      if (!sampler.admissible(node)) continue;
      Vector2 p = node;
      for (int attempt = 0; attempt < 100 && jitter_mm > 0; ++attempt) {
        p = node + Vector2(sampler.uniform(-jitter_mm, jitter_mm), sampler.uniform(-jitter_mm, jitter_mm));
        if (sampler.admissible(p)) break;
        p = node;
      }
      frames.push_back({sampler.press_at(p)});
    }
  if (frames.empty()) throw InvalidInput("the grid has no point inside the sheet's margin");
  return frames;
}

PressSequence random_script(const Sensor& sensor, int frames, const PressStyle& style) {
  if (frames < 1) throw InvalidInput("frames must be at least 1");
  Sampler sampler(sensor, style);
  PressSequence sequence;
  for (int f = 0; f < frames; ++f) sequence.push_back({sampler.press_at(sampler.random_point())});
  return sequence;
}

PressSequence two_finger_script(const Sensor& sensor, int frames, double min_separation_mm, double max_separation_mm,
                                const PressStyle& style) {
  if (frames < 1) throw InvalidInput("frames must be at least 1");
  if (!(min_separation_mm > 0) || max_separation_mm < min_separation_mm)
    throw InvalidInput("separations must satisfy 0 < min <= max");
  Sampler sampler(sensor, style);
  PressSequence sequence;
  for (int f = 0; f < frames; ++f) {
    for (int attempt = 0;; ++attempt) {
      if (attempt == 100000) throw InvalidInput("no room on the sheet for two presses that far apart");
      const Vector2 a = sampler.random_point();
      const double angle = sampler.uniform(0, 2 * std::numbers::pi);
      const double separation = sampler.uniform(min_separation_mm, max_separation_mm);
      const Vector2 b = a + separation * Vector2(std::cos(angle), std::sin(angle));
      if (!sampler.admissible(b)) continue;
      sequence.push_back({sampler.press_at(a), sampler.press_at(b)});
      break;
    }
  }
  return sequence;
}

PressSequence fingers_script(const Sensor& sensor, int frames, int fingers, double min_separation_mm,
                             const PressStyle& style) {
  if (frames < 1) throw InvalidInput("frames must be at least 1");
  if (fingers < 1) throw InvalidInput("fingers must be at least 1");
  if (!(min_separation_mm > 0)) throw InvalidInput("the fingers' separation must be positive");
  Sampler sampler(sensor, style);
  PressSequence sequence;
  for (int f = 0; f < frames; ++f) {
    // Place the fingers one by one, each far enough from those placed; after 1000 misses in a
    // row the first ones may have crowded the sheet, so start the frame again.
    std::vector<Vector2> placed;
    for (int tries = 0, misses = 0; static_cast<int>(placed.size()) < fingers; ++tries) {
      if (tries == 200'000) {
        char message[128];
        std::snprintf(message, sizeof message, "no room on the sheet for %d presses %g mm apart", fingers,
                      min_separation_mm);
        throw InvalidInput(message);
      }
      const Vector2 p = sampler.random_point();
      if (std::all_of(placed.begin(), placed.end(),
                      [&](const Vector2& q) { return (p - q).norm() >= min_separation_mm; })) {
        placed.push_back(p), misses = 0;
      } else if (++misses == 1000) {
        placed.clear(), misses = 0;
      }
    }
    std::vector<Press> presses;
    presses.reserve(placed.size());
    for (const Vector2& p : placed) presses.push_back(sampler.press_at(p));  // forces drawn finger by finger
    sequence.push_back(presses);
  }
  return sequence;
}

PressSequence moving_script(const Sensor& sensor, int frames, const Vector2& from_mm, const Vector2& to_mm,
                            const PressStyle& style) {
  if (frames < 2) throw InvalidInput("a moving press needs at least 2 frames");
  Sampler sampler(sensor, style);
  PressSequence sequence;
  for (int f = 0; f < frames; ++f) {
    const Vector2 p = from_mm + (to_mm - from_mm) * (static_cast<double>(f) / (frames - 1));
    if (!sampler.admissible(p))
      throw InvalidInput("the moving press's path leaves the sheet (or its margin) at frame " + std::to_string(f));
    sequence.push_back({sampler.press_at(p)});
  }
  return sequence;
}

PressSequence crossing_script(const Sensor& sensor, int frames, double min_separation_mm, double max_separation_mm,
                              const PressStyle& style) {
  if (frames < 2) throw InvalidInput("two crossing fingers need at least 2 frames");
  if (!(min_separation_mm > 0) || max_separation_mm < min_separation_mm)
    throw InvalidInput("separations must satisfy 0 < min <= max");
  Sampler sampler(sensor, style);
  for (int attempt = 0; attempt < 10000; ++attempt) {
    const Vector2 centre = sampler.random_point();
    const double angle = sampler.uniform(0, 2 * std::numbers::pi);
    const double separation_mm = sampler.uniform(min_separation_mm, max_separation_mm);
    const double length_a_mm = sampler.uniform(10, 40), length_b_mm = sampler.uniform(10, 40);
    double low_N = sampler.force(), high_N = sampler.force();
    if (low_N > high_N) std::swap(low_N, high_N);
    const Vector2 along(std::cos(angle), std::sin(angle)), across(-along.y(), along.x());
    PressSequence sequence;
    for (int f = 0; f < frames; ++f) {
      const double share = static_cast<double>(f) / (frames - 1), from_middle = share - 0.5;
      const Vector2 a = centre + from_middle * length_a_mm * along + 0.5 * separation_mm * across;
      const Vector2 b = centre - from_middle * length_b_mm * along - 0.5 * separation_mm * across;
      if (!sampler.admissible(a) || !sampler.admissible(b)) break;
      Press first = sampler.press_at(a), second = sampler.press_at(b);
      first.force_N = low_N + share * (high_N - low_N);
      second.force_N = high_N - share * (high_N - low_N);
      sequence.push_back({first, second});
    }
    if (static_cast<int>(sequence.size()) == frames) return sequence;
  }
  throw InvalidInput("no room on the sheet for two fingers crossing that far apart");
}

PressScript::Kind parse_script_kind(const std::string& name) {
  if (name == "none") return PressScript::Kind::none;
  if (name == "grid") return PressScript::Kind::grid;
  if (name == "random") return PressScript::Kind::random;
  if (name == "two-finger") return PressScript::Kind::two_finger;
  if (name == "three-finger") return PressScript::Kind::three_finger;
  if (name == "four-finger") return PressScript::Kind::four_finger;
  if (name == "moving") return PressScript::Kind::moving;
  if (name == "crossing") return PressScript::Kind::crossing;
  if (name == "calibration") return PressScript::Kind::calibration;
  throw InvalidInput("--script: unknown script " + quote_input(name) +
                     " (none, grid, random, two-finger, three-finger, four-finger, moving, crossing, calibration)");
}

double script_frame_count(const Sensor& sensor, const PressScript& script) {
  if (script.kind == PressScript::Kind::calibration) {
    if (!(script.frames_per_s > 0) || !std::isfinite(script.frames_per_s)) return 0;  // run_script says so
    return std::ceil(CalibrationPerson(sensor, script.person).duration_s() * script.frames_per_s);
  }
  if (script.kind != PressScript::Kind::grid) return script.frames;
  if (!(script.spacing_mm > 0)) return 0;  // grid_script says what is wrong
  return grid_node_count(grid_half_counts(bounding_box(sheet_outline(sensor)), script.spacing_mm));
}

PressSequence run_script(const Sensor& sensor, const PressScript& script) {
  switch (script.kind) {
    case PressScript::Kind::none: return PressSequence(static_cast<std::size_t>(script.frames));
    case PressScript::Kind::grid: return grid_script(sensor, script.spacing_mm, script.jitter_mm, script.style);
    case PressScript::Kind::random: return random_script(sensor, script.frames, script.style);
    case PressScript::Kind::two_finger:
      return two_finger_script(sensor, script.frames, script.min_separation_mm, script.max_separation_mm, script.style);
    case PressScript::Kind::three_finger:
      return fingers_script(sensor, script.frames, 3, script.min_separation_mm, script.style);
    case PressScript::Kind::four_finger:
      return fingers_script(sensor, script.frames, 4, script.min_separation_mm, script.style);
    case PressScript::Kind::moving:
      return moving_script(sensor, script.frames, script.from_mm, script.to_mm, script.style);
    case PressScript::Kind::crossing:
      return crossing_script(sensor, script.frames, script.min_separation_mm, script.max_separation_mm, script.style);
    case PressScript::Kind::calibration: return CalibrationPerson(sensor, script.person).frames(script.frames_per_s);
  }
  return {};
}

}  // namespace emit
