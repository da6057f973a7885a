#include <unistd.h>
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <memory>

#include "commands.hpp"
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

std::vector<std::string> method_names() {
  return {method_name(Method::fit), method_name(Method::paper), method_name(Method::noser),
          method_name(Method::laplacian)};
}

std::string cache_dir_option(const std::string& cache_dir, bool no_cache) {
  return no_cache ? "" : (cache_dir.empty() ? default_cache_dir() : cache_dir);
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
