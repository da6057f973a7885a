#include "emit/twin/sim_source.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <random>
#include <utility>

#include "emit/core/errors.hpp"
#include "emit/mesh/sheet_chart.hpp"
#include "emit/sensor/press.hpp"
#include "emit/sensor/press_outline.hpp"
#include "emit/sensor/surface.hpp"

namespace emit {

namespace {

constexpr double loop_pressed_s = 6, loop_lifted_s = 1;  // the figure-eight, then a lift-off
constexpr double random_pressed_s = 0.6, random_lifted_s = 0.2;
constexpr double force_swing_period_s = 3;
constexpr double script_clock_frames_per_s = 50;  // the scripts' clock when frames come unpaced
constexpr double pace_budget = 0.8;               // of the frame interval the twin may take: the rest is headroom

double parse_number(const std::string& text, const std::string& spec) {
  try {
    std::size_t used = 0;
    const double value = std::stod(text, &used);
    if (used == text.size() && std::isfinite(value)) return value;
  } catch (const std::exception&) {
  }
  throw InvalidInput("source \"" + spec + "\": \"" + text + "\" is not a number");
}

bool admissible(const Sensor& sensor, const Mesh& mesh, const Vector2& p, double margin_mm) {
  // A file's sheet read with its surface has an outline too (sensor/height_field.hpp).
  if (sensor.border || (sensor.shape.surface && sensor.shape.surface->outline()))
    return chart_distance_to_border_mm(sensor.shape, sheet_outline(sensor), p) >= margin_mm;
  return mesh.contains_xy(p);
}

}  // namespace

SimScript parse_sim_script(const std::string& spec) {
  SimScript script;
  if (spec == "sim" || spec == "sim:loop") return script;
  if (spec == "sim:random") {
    script.kind = SimScript::Kind::random;
    return script;
  }
  const std::string fixed = "sim:fixed:";
  if (spec.rfind(fixed, 0) != 0)
    throw InvalidInput("source \"" + spec + "\": expected sim, sim:random, sim:fixed:X,Y[,F] or sim:fixed:OUTLINE");
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

SimSource::SimSource(const Sensor& sensor, SimScript script, const SourceOptions& options)
    : sensor_(sensor), script_(std::move(script)), options_(options), twin_(sensor, [&] {
        TwinOptions twin;
        twin.noise_seed = options.seed;
        twin.condensed_frames = true;  // the direct solve's frames, several times faster
        return twin;
      }()) {
  if (!(options.frames_per_s >= 0) || !std::isfinite(options.frames_per_s))
    throw InvalidInput("source: frames per second must be 0 (unpaced) or positive");
  if (options.untouched_frames < 0) throw InvalidInput("source: untouched frames must not be negative");
  // The scripts move over the sheet's chart (sensor/surface.hpp).
  const Eigen::AlignedBox2d box = chart_box(twin_.mesh(), sensor_.shape);
  center_mm_ = box.center();
  half_extent_mm_ = box.sizes() / 2;
  if (script_.kind == SimScript::Kind::fixed) {
    // X, Y name the sheet's point seen from +z: on a cylinder, the upper one above (X, Y).
    script_.fixed.z_mm = surface_point_above_mm(sensor_.shape, {script_.fixed.x_mm, script_.fixed.y_mm}).z();
    validate_press(sensor_, script_.fixed, "source sim:fixed");
  }
  frames_per_s_ = options_.frames_per_s;
  measure_pace();
}

void SimSource::measure_pace() {
  // A few pressed frames of the script, spread over it (exact frames: the ADC's noise stream is
  // left as it was); the first is a warm-up.
  std::vector<std::vector<Press>> pressed;
  for (std::uint64_t k = 0; k < 400 && pressed.size() < 4; k += 37)
    if (auto presses = presses_of(static_cast<std::uint64_t>(options_.untouched_frames) + k); !presses.empty())
      pressed.push_back(std::move(presses));
  if (pressed.empty()) return;
  twin_.exact_frame(pressed.front());
  const auto start = std::chrono::steady_clock::now();
  for (const auto& presses : pressed) twin_.exact_frame(presses);
  measured_frame_s_ = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count() /
                      static_cast<double>(pressed.size());
  if (options_.frames_per_s > 0 && measured_frame_s_ > pace_budget / options_.frames_per_s)
    frames_per_s_ = std::max(1.0, std::floor(pace_budget / measured_frame_s_));
}

Press SimSource::press_at(const Vector2& chart_mm, double force_N) const {
  return press_at_chart(sensor_.shape, chart_mm, script_.radius_mm, force_N);
}

SimSource::~SimSource() {
  {
    std::lock_guard lock(mutex_);
    stop_ = true;
  }
  ready_.notify_all();
  if (thread_.joinable()) thread_.join();
}

double SimSource::script_time_s(std::uint64_t sequence) const {
  const double rate = frames_per_s_ > 0 ? frames_per_s_ : script_clock_frames_per_s;
  return (static_cast<double>(sequence) - options_.untouched_frames) / rate;
}

std::vector<Press> SimSource::presses_of(std::uint64_t sequence) const {
  const double t = script_time_s(sequence);
  if (t < 0) return {};
  switch (script_.kind) {
    case SimScript::Kind::fixed: return {script_.fixed};
    case SimScript::Kind::loop: {
      const double phase = std::fmod(t, loop_pressed_s + loop_lifted_s);
      if (phase >= loop_pressed_s) return {};
      const double w = 2 * std::numbers::pi * phase / loop_pressed_s;  // one figure-eight per press
      const double swing = 0.5 - 0.5 * std::cos(2 * std::numbers::pi * t / force_swing_period_s);
      const Vector2 p =
          center_mm_ + Vector2(0.55 * half_extent_mm_.x() * std::sin(w), 0.4 * half_extent_mm_.y() * std::sin(2 * w));
      return {press_at(p, script_.min_force_N + swing * (script_.max_force_N - script_.min_force_N))};
    }
    case SimScript::Kind::random: {
      const double period = random_pressed_s + random_lifted_s;
      const auto block = static_cast<std::uint64_t>(t / period);
      if (t - static_cast<double>(block) * period >= random_pressed_s) return {};
      std::mt19937_64 rng(options_.seed * 0x9E3779B97F4A7C15ull + block);  // the same press for every frame of a block
      std::uniform_real_distribution<double> u(0, 1);
      const double margin_mm = script_.radius_mm + 3;
      for (int attempt = 0; attempt < 1000; ++attempt) {
        const Vector2 p =
            center_mm_ + Vector2((2 * u(rng) - 1) * half_extent_mm_.x(), (2 * u(rng) - 1) * half_extent_mm_.y());
        if (admissible(sensor_, twin_.mesh(), p, margin_mm))
          return {press_at(p, script_.min_force_N + u(rng) * (script_.max_force_N - script_.min_force_N))};
      }
      return {};
    }
  }
  return {};
}

void SimSource::produce() {
  const auto start = std::chrono::steady_clock::now();
  try {
    for (std::uint64_t sequence = 0;; ++sequence) {
      SourceFrame frame;
      const auto making = std::chrono::steady_clock::now();
      frame.volts = twin_.frame(presses_of(sequence), &frame.raw.counts);
      const double made_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - making).count();
      frame.sequence = sequence;
      const double due_s = frames_per_s_ > 0 ? static_cast<double>(sequence) / frames_per_s_ : 0;
      const auto due =
          start + std::chrono::duration_cast<std::chrono::steady_clock::duration>(std::chrono::duration<double>(due_s));
      std::unique_lock lock(mutex_);
      making_s_ += made_s;
      ++made_;
      if (ready_.wait_until(lock, due, [this] { return stop_; })) return;
      frame.received = std::chrono::steady_clock::now();
      frame.board_time_s = frames_per_s_ > 0 ? due_s : std::chrono::duration<double>(frame.received - start).count();
      frame.raw.sequence = static_cast<std::uint32_t>(sequence);  // the packet's fields wrap, as the board's do
      frame.raw.timestamp_us =
          static_cast<std::uint32_t>(static_cast<std::uint64_t>(std::llround(frame.board_time_s * 1e6)));
      frame.raw.electrode_count = static_cast<int>(frame.volts.rows());
      frame.raw.adc_bits = sensor_.adc.bits;
      frame.raw.oversampling = 1;
      if (frames_per_s_ == 0) {  // unpaced: the twin waits for the reader, so every frame is read
        ready_.wait(lock, [this] { return stop_ || queue_.size() < queue_limit; });
        if (stop_) return;
      } else if (queue_.size() >= queue_limit) {  // paced like a board: its frames come whether read or not
        queue_.pop_front();
        ++dropped_;
      }
      queue_.push_back(std::move(frame));
      lock.unlock();
      ready_.notify_all();
    }
  } catch (const std::exception& e) {
    std::lock_guard lock(mutex_);
    failure_ = std::make_exception_ptr(IoError(std::string("source sim: ") + e.what()));
  }
  ready_.notify_all();
}

bool SimSource::next(SourceFrame& frame, std::chrono::milliseconds timeout) {
  // The twin starts on the first call, not at construction: frames made while the reader is
  // still building its models would only pile up (and the baseline must see the untouched ones).
  if (!thread_.joinable()) thread_ = std::thread([this] { produce(); });
  std::unique_lock lock(mutex_);
  ready_.wait_for(lock, timeout, [this] { return !queue_.empty() || failure_; });
  if (!queue_.empty()) {
    frame = std::move(queue_.front());
    queue_.pop_front();
    lock.unlock();
    ready_.notify_all();  // an unpaced twin may be waiting for room
    return true;
  }
  if (failure_) std::rethrow_exception(failure_);
  return false;
}

bool SimSource::finished() const {
  std::lock_guard lock(mutex_);
  return failure_ && queue_.empty();
}

double SimSource::frame_cost_s() const {
  std::lock_guard lock(mutex_);
  return made_ > 0 ? making_s_ / static_cast<double>(made_) : 0;
}

std::uint64_t SimSource::dropped() const {
  std::lock_guard lock(mutex_);
  return dropped_;
}

std::string SimSource::description() const {
  char rate[160];
  if (frames_per_s_ > 0 && frames_per_s_ < options_.frames_per_s)
    std::snprintf(rate, sizeof rate,
                  "%g frames/s asked, but a twin frame takes %.1f ms on this machine: running at %g frames/s",
                  options_.frames_per_s, 1e3 * measured_frame_s_, frames_per_s_);
  else if (frames_per_s_ > 0)
    std::snprintf(rate, sizeof rate, "%g frames/s (a twin frame takes %.1f ms)", frames_per_s_,
                  1e3 * measured_frame_s_);
  else std::snprintf(rate, sizeof rate, "as fast as the twin goes");
  std::string what;
  switch (script_.kind) {
    case SimScript::Kind::loop: what = "a finger moving in a figure-eight"; break;
    case SimScript::Kind::random: what = "presses at random places"; break;
    case SimScript::Kind::fixed: {
      char text[96];
      std::snprintf(text, sizeof text, "a press held at (%g, %g) mm, %g N", script_.fixed.x_mm, script_.fixed.y_mm,
                    script_.fixed.force_N);
      what = text;
    }
  }
  return "sim: " + what + " on " + sensor_.name + ", " + rate + ", ADC noise on";
}

}  // namespace emit
