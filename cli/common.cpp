#include <unistd.h>
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <memory>

#include "commands.hpp"
#include "emit/core/quote_input.hpp"
#include "emit/model/operator_cache.hpp"

namespace emit::cli {

Progress stderr_progress(long min_count) {
  struct State {
    bool tty = ::isatty(2) != 0;
    long last_percent = -1;
  };
  auto state = std::make_shared<State>();
  Progress progress;
  progress.stage = [](const std::string& stage) { std::fprintf(stderr, "%s ...\n", stage.c_str()); };
  progress.warning = [](const std::string& message) { std::fprintf(stderr, "emit: warning: %s\n", message.c_str()); };
  progress.count = [state, min_count](const std::string& what, long done, long total) {
    if (total < std::max(min_count, 1L)) return;
    const long percent = 100 * done / total;
    if (state->tty)
      std::fprintf(stderr, "\r%s %ld/%ld (%ld%%)%s", what.c_str(), done, total, percent, done == total ? "\n" : "");
    else if (percent / 10 != state->last_percent / 10)
      std::fprintf(stderr, "%s %ld/%ld (%ld%%)\n", what.c_str(), done, total, percent);
    state->last_percent = done == total ? -1 : percent;
  };
  return progress;
}

namespace {

/// A validator accepting a whole number (integer) or any number, and `rule` holding for it.
CLI::Validator number_validator(const std::string& name, bool integer, bool (*rule)(double), const std::string& what) {
  return CLI::Validator(
      [=](const std::string& text) -> std::string {
        double value = 0;
        char* end = nullptr;
        value = std::strtod(text.c_str(), &end);
        const bool whole = end != text.c_str() && *end == '\0' && std::isfinite(value);
        if (whole && (!integer || value == std::floor(value)) && rule(value)) return {};
        return "must be " + what + ", got " + quote_input(text);
      },
      name);
}

}  // namespace

const CLI::Validator& positive_number() {
  static const CLI::Validator v = number_validator(
      "POSITIVE", false, [](double x) { return x > 0; }, "a positive number");
  return v;
}

const CLI::Validator& non_negative_number() {
  static const CLI::Validator v = number_validator(
      "NONNEGATIVE", false, [](double x) { return x >= 0; }, "a number 0 or larger");
  return v;
}

const CLI::Validator& fraction_below_one() {
  static const CLI::Validator v = number_validator(
      "FRACTION", false, [](double x) { return x >= 0 && x < 1; }, "a fraction from 0 up to (not including) 1");
  return v;
}

const CLI::Validator& positive_integer() {
  static const CLI::Validator v = number_validator(
      "POSITIVE", true, [](double x) { return x > 0; }, "a whole number 1 or larger");
  return v;
}

const CLI::Validator& non_negative_integer() {
  static const CLI::Validator v = number_validator(
      "NONNEGATIVE", true, [](double x) { return x >= 0; }, "a whole number 0 or larger");
  return v;
}

namespace {

std::size_t edit_distance(const std::string& a, const std::string& b) {
  std::vector<std::size_t> row(b.size() + 1);
  for (std::size_t j = 0; j <= b.size(); ++j) row[j] = j;
  for (std::size_t i = 1; i <= a.size(); ++i) {
    std::size_t diagonal = row[0];
    row[0] = i;
    for (std::size_t j = 1; j <= b.size(); ++j) {
      const std::size_t up = row[j];
      row[j] = std::min({row[j] + 1, row[j - 1] + 1, diagonal + (a[i - 1] == b[j - 1] ? 0 : 1)});
      diagonal = up;
    }
  }
  return row[b.size()];
}

}  // namespace

std::string parse_error_message(const CLI::App& app, const CLI::ParseError& error, int argc, char** argv) {
  if (app.get_subcommands().empty()) {
    // The first word that is not an option or an option's value: the command the user meant.
    for (int i = 1; i < argc; ++i) {
      const std::string word = argv[i];
      if (word == "--threads") {
        ++i;
        continue;
      }
      if (word.rfind('-', 0) == 0) continue;
      std::string nearest;
      std::size_t best = 3;  // at most two edits away
      for (const CLI::App* command : app.get_subcommands([](const CLI::App*) { return true; })) {
        if (word == command->get_name()) return error.what();  // a command: the error is another
        if (const std::size_t d = edit_distance(word, command->get_name()); d < best)
          best = d, nearest = command->get_name();
      }
      return "unknown command " + quote_input(word) + (nearest.empty() ? "" : " (did you mean \"" + nearest + "\"?)");
    }
    return "no command given: try 'emit demo'";
  }
  return error.what();
}

std::string cache_dir_option(const std::string& cache_dir, bool no_cache) {
  return no_cache ? "" : (cache_dir.empty() ? default_cache_dir() : cache_dir);
}

std::string examples_dir() {
  std::error_code error;
  const std::filesystem::path command = std::filesystem::read_symlink("/proc/self/exe", error);
  if (!error) {
    const std::filesystem::path installed = command.parent_path().parent_path() / EMIT_INSTALLED_EXAMPLES_DIR;
    if (std::filesystem::is_directory(installed, error)) return installed.string();
  }
  return EMIT_EXAMPLES_DIR;
}

void print_frames_summary(const std::vector<Frame>& frames, const PressSequence& presses) {
  std::printf("%5s %8s %8s  %-13s  %s\n", "frame", "max V", "mean V", "ground->sense",
              "presses (x mm, y mm, r mm, F N)");
  for (std::size_t f = 0; f < frames.size(); ++f) {
    const Frame& frame = frames[f];
    const Index N = frame.rows();
    double max_value = -1, sum = 0;
    Index top_l = 0, top_m = 0;
    for (Index l = 0; l < N; ++l)
      for (Index m = 0; m < N; ++m) {
        if (l == m) continue;
        sum += frame(l, m);
        if (frame(l, m) > max_value) max_value = frame(l, m), top_l = l, top_m = m;
      }
    std::string text;
    char item[80];
    for (const Press& p : f < presses.size() ? presses[f] : std::vector<Press>{}) {
      std::snprintf(item, sizeof item, "%s(%.1f, %.1f, %.1f, %.1f)", text.empty() ? "" : " ", p.x_mm, p.y_mm,
                    p.radius_mm, p.force_N);
      text += item;
    }
    std::snprintf(item, sizeof item, "%lld->%lld", static_cast<long long>(top_l), static_cast<long long>(top_m));
    std::printf("%5zu %8.4f %8.4f  %-13s  %s\n", f, max_value, sum / double(N * (N - 1)), item,
                text.empty() ? "none" : text.c_str());
  }
}

void print_frame_table(const Frame& frame) {
  std::printf("ground\\sense");
  for (Index m = 0; m < frame.cols(); ++m) std::printf(" %7lld", static_cast<long long>(m));
  std::printf("\n");
  for (Index l = 0; l < frame.rows(); ++l) {
    std::printf("%12lld", static_cast<long long>(l));
    for (Index m = 0; m < frame.cols(); ++m) std::printf(" %7.4f", std::abs(frame(l, m)) < 5e-5 ? 0.0 : frame(l, m));
    std::printf("\n");
  }
}

}  // namespace emit::cli
