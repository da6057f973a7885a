#include "emit/twin/sim_script.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <numbers>
#include <random>
#include <utility>

#include "emit/core/errors.hpp"
#include "emit/mesh/sheet_chart.hpp"
#include "emit/sensor/press_outline.hpp"
#include "emit/sensor/surface.hpp"

namespace emit {

namespace {

constexpr double loop_pressed_s = 6, loop_lifted_s = 1;  // the figure-eight, then a lift-off
constexpr double random_pressed_s = 0.6, random_lifted_s = 0.2;
constexpr double force_swing_period_s = 3;
constexpr double script_clock_frames_per_s = 50;  // the scripts' clock when frames come unpaced
/// The figure-eight's reach from the middle, as fractions of the chart box's half sizes (x, y),
/// when the sheet has room for it; else the largest fraction of it that stays clear of the border.
constexpr double loop_reach_x = 0.55, loop_reach_y = 0.4;

double parse_number(const std::string& text, const std::string& spec) {
  try {
    std::size_t used = 0;
    const double value = std::stod(text, &used);
    if (used == text.size() && std::isfinite(value)) return value;
  } catch (const std::exception&) {
  }
  throw InvalidInput("source \"" + spec + "\": \"" + text + "\" is not a number");
}

/// The border's points on the surface, every `spacing_mm` or closer along it in the chart.
constexpr double border_spacing_mm = 0.25;

bool has_outline(const Sensor& sensor) {
  // A file's sheet read with its surface has an outline too (sensor/height_field.hpp).
  return sensor.border || (sensor.shape.surface && sensor.shape.surface->outline());
}

}  // namespace

double ScriptedPresses::room_mm(const Vector2& chart_mm) const {
  // A sleeve's seam is no border: its ends are, as far in 3D as along its axis.
  if (!has_outline(sensor_) || is_sleeve(sensor_.shape)) {
    if (has_outline(sensor_)) return chart_distance_to_border_mm(sensor_.shape, sheet_outline(sensor_), chart_mm);
    return mesh_.contains_xy(chart_mm) ? std::numeric_limits<double>::infinity() : -1;
  }
  const Border& outline = sheet_outline(sensor_);
  if (!outline.contains(chart_mm)) return -outline.distance_to_border_mm(chart_mm);
  const Vector3 centre = surface_point_mm(sensor_.shape, chart_mm);
  double nearest = std::numeric_limits<double>::infinity();
  for (const Vector3& b : border_points_mm_) nearest = std::min(nearest, (b - centre).squaredNorm());
  return std::sqrt(nearest);
}

SimScript parse_sim_script(const std::string& spec) {
  SimScript script;
  if (spec == "sim" || spec == "sim:loop") return script;
  if (spec == "sim:random") {
    script.kind = SimScript::Kind::random;
    return script;
  }
  if (const std::string calibration = "sim:calibration"; spec.rfind(calibration, 0) == 0) {
    script.kind = SimScript::Kind::calibration;
    if (spec == calibration) return script;
    const std::string count = spec.substr(calibration.size());
    const double presses = count.size() > 1 && count[0] == ':' ? parse_number(count.substr(1), spec) : -1;
    if (!(presses >= 0 && presses <= 100000 && presses == std::floor(presses)))
      throw InvalidInput("source \"" + spec + "\": expected sim:calibration or sim:calibration:PRESSES (a count)");
    script.person.presses = static_cast<int>(presses);
    return script;
  }
  if (spec == "sim:fixed") {  // held at the sheet's middle (SimSource's constructor finds it)
    script.kind = SimScript::Kind::fixed;
    script.fixed_at_middle = true;
    return script;
  }
  const std::string fixed = "sim:fixed:";
  if (spec.rfind(fixed, 0) != 0)
    throw InvalidInput("source \"" + spec +
                       "\": expected sim, sim:random, sim:calibration[:PRESSES], sim:fixed, sim:fixed:X,Y[,F] or "
                       "sim:fixed:OUTLINE");
  if (const std::string outline = spec.substr(fixed.size()); outline.find(':') != std::string::npos) {
    // A flat punch of another outline (bar:…, ellipse:…, ring:…, polygon:…), as `simulate --press`.
    script.kind = SimScript::Kind::fixed;
    try {
      script.fixed = parse_outline_press(outline);
    } catch (const InvalidInput& e) {
      throw InvalidInput("source \"" + spec + "\": " + e.what());
    }
    return script;
  }
  std::vector<double> values;
  std::string rest = spec.substr(fixed.size());
  for (std::size_t at; !rest.empty();) {
    at = rest.find(',');
    values.push_back(parse_number(rest.substr(0, at), spec));
    rest = at == std::string::npos ? "" : rest.substr(at + 1);
  }
  if (values.size() < 2 || values.size() > 3)
    throw InvalidInput("source \"" + spec + "\": sim:fixed takes X,Y or X,Y,F (mm, mm, N)");
  script.kind = SimScript::Kind::fixed;
  script.fixed = Press{values[0], values[1], script.radius_mm, values.size() == 3 ? values[2] : 10.0};
  return script;
}

ScriptedPresses::ScriptedPresses(const Sensor& sensor, const Mesh& mesh, SimScript script, const SourceOptions& options)
    : sensor_(sensor), mesh_(mesh), script_(std::move(script)), options_(options) {
  if (!(options.frames_per_s >= 0) || !std::isfinite(options.frames_per_s))
    throw InvalidInput("source: frames per second must be 0 (unpaced) or positive");
  if (options.untouched_frames < 0) throw InvalidInput("source: untouched frames must not be negative");
  // The scripts move over the sheet's chart (sensor/surface.hpp).
  const Eigen::AlignedBox2d box = chart_box(mesh_, sensor_.shape);
  center_mm_ = box.center();
  half_extent_mm_ = box.sizes() / 2;
  if (has_outline(sensor_) && !is_sleeve(sensor_.shape)) {
    const Border& outline = sheet_outline(sensor_);
    const auto samples = static_cast<int>(std::ceil(outline.length_mm() / border_spacing_mm));
    border_points_mm_.reserve(static_cast<std::size_t>(samples));
    for (int k = 0; k < samples; ++k)
      border_points_mm_.push_back(surface_point_mm(sensor_.shape, outline.point_at(outline.length_mm() * k / samples)));
  }
  const double least_room_mm = script_.radius_mm + margin_mm;
  if ((script_.kind == SimScript::Kind::loop || script_.fixed_at_middle) && room_mm(center_mm_) < least_room_mm) {
    char text[160];
    std::snprintf(text, sizeof text, "source sim: the sheet's middle (%g, %g) mm is within %g mm of its border",
                  center_mm_.x(), center_mm_.y(), least_room_mm);
    throw InvalidInput(std::string(text) + ": hold a press where there is room (sim:fixed:X,Y) or use sim:random");
  }
  if (script_.kind == SimScript::Kind::loop) {
    // The largest figure-eight (up to its full reach) whose every point keeps the margin: a
    // narrow or odd sheet gets a smaller one, never a press off it.
    const auto fits = [&](double scale) {
      for (int k = 0; k < 720; ++k) {
        const double w = 2 * std::numbers::pi * k / 720;
        if (room_mm(loop_point(w, scale)) < least_room_mm) return false;
      }
      return true;
    };
    while (loop_scale_ > 0.05 && !fits(loop_scale_)) loop_scale_ *= 0.9;
    if (!fits(loop_scale_)) loop_scale_ = 0;  // a press held at the middle, moving no more
  }
  if (script_.kind == SimScript::Kind::calibration) {
    CalibrationPersonOptions person = script_.person;
    person.seed = options.seed;
    person_.emplace(sensor_, person);
  }
  if (script_.fixed_at_middle) {
    script_.fixed = press_at(center_mm_, script_.fixed.force_N);
  } else if (script_.kind == SimScript::Kind::fixed) {
    // X, Y name the sheet's point seen from +z: on a cylinder, the upper one above (X, Y).
    script_.fixed.z_mm = surface_point_above_mm(sensor_.shape, {script_.fixed.x_mm, script_.fixed.y_mm}).z();
    validate_press(sensor_, script_.fixed, "source sim:fixed");
  }
}

Vector2 ScriptedPresses::loop_point(double w, double scale) const {
  return center_mm_ + scale * Vector2(loop_reach_x * half_extent_mm_.x() * std::sin(w),
                                      loop_reach_y * half_extent_mm_.y() * std::sin(2 * w));
}

Press ScriptedPresses::press_at(const Vector2& chart_mm, double force_N) const {
  return press_at_chart(sensor_.shape, chart_mm, script_.radius_mm, force_N);
}

double ScriptedPresses::script_time_s(std::uint64_t sequence) const {
  const double rate = options_.frames_per_s > 0 ? options_.frames_per_s : script_clock_frames_per_s;
  return (static_cast<double>(sequence) - options_.untouched_frames) / rate;
}

std::vector<Press> ScriptedPresses::presses_of(std::uint64_t sequence) const {
  const double t = script_time_s(sequence);
  if (t < 0) return {};
  switch (script_.kind) {
    case SimScript::Kind::fixed: return {script_.fixed};
    case SimScript::Kind::calibration: {
      const Press* press = person_->press_at(t);
      return press ? std::vector<Press>{*press} : std::vector<Press>{};
    }
    case SimScript::Kind::loop: {
      const double phase = std::fmod(t, loop_pressed_s + loop_lifted_s);
      if (phase >= loop_pressed_s) return {};
      const double w = 2 * std::numbers::pi * phase / loop_pressed_s;  // one figure-eight per press
      const double swing = 0.5 - 0.5 * std::cos(2 * std::numbers::pi * t / force_swing_period_s);
      return {press_at(loop_point(w, loop_scale_),
                       script_.min_force_N + swing * (script_.max_force_N - script_.min_force_N))};
    }
    case SimScript::Kind::random: {
      const double period = random_pressed_s + random_lifted_s;
      const auto block = static_cast<std::uint64_t>(t / period);
      if (t - static_cast<double>(block) * period >= random_pressed_s) return {};
      std::mt19937_64 rng(options_.seed * 0x9E3779B97F4A7C15ull + block);  // the same press for every frame of a block
      std::uniform_real_distribution<double> u(0, 1);
      const double least_room_mm = script_.radius_mm + margin_mm;
      for (int attempt = 0; attempt < 1000; ++attempt) {
        const Vector2 p =
            center_mm_ + Vector2((2 * u(rng) - 1) * half_extent_mm_.x(), (2 * u(rng) - 1) * half_extent_mm_.y());
        if (room_mm(p) >= least_room_mm)
          return {press_at(p, script_.min_force_N + u(rng) * (script_.max_force_N - script_.min_force_N))};
      }
      return {};
    }
  }
  return {};
}

std::string ScriptedPresses::description() const {
  switch (script_.kind) {
    case SimScript::Kind::loop: return "a finger moving in a figure-eight";
    case SimScript::Kind::random: return "presses at random places";
    case SimScript::Kind::calibration: {
      std::string text = "a person calibrating: lifted for the first " +
                         std::to_string(script_.person.quiet_s).substr(0, 4) + " s, " +
                         std::to_string(person_->presses().size()) + " presses in all, the last " +
                         std::to_string(script_.person.weights_N.size()) + " known weights (";
      char weight[32];
      for (std::size_t i = 0; i < script_.person.weights_N.size(); ++i) {
        std::snprintf(weight, sizeof weight, "%s%g N", i > 0 ? ", " : "", script_.person.weights_N[i]);
        text += weight;
      }
      return text + ")";
    }
    case SimScript::Kind::fixed: {
      char text[128];
      std::snprintf(text, sizeof text, "a press held at (%g, %g) mm, %g N%s", script_.fixed.x_mm, script_.fixed.y_mm,
                    script_.fixed.force_N, script_.fixed_at_middle ? " (the sheet's middle)" : "");
      return text;
    }
  }
  return "";
}

}  // namespace emit
