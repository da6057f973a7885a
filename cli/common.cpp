#include <algorithm>
#include <cmath>
#include <cstdio>
#include <unistd.h>

#include "commands.hpp"
#include "emit/sensor/sensor_json.hpp"

namespace emit::cli {

Sensor sensor_from_option(const std::string& path) { return path.empty() ? default_sensor() : load_sensor(path); }

Progress::Progress(std::string what, int total) : what_(std::move(what)), total_(std::max(total, 1)), tty_(::isatty(2)) {}

void Progress::step(int done) {
  const int percent = 100 * done / total_;
  if (tty_) {
    std::fprintf(stderr, "\r%s %d/%d (%d%%)", what_.c_str(), done, total_, percent);
  } else if (percent / 10 != last_percent_ / 10) {
    std::fprintf(stderr, "%s %d/%d (%d%%)\n", what_.c_str(), done, total_, percent);
  }
  last_percent_ = percent;
}

void Progress::finish() {
  if (tty_) std::fprintf(stderr, "\r%s %d/%d (100%%)\n", what_.c_str(), total_, total_);
}

void print_frames_summary(const std::vector<Frame>& frames, const PressSequence& presses) {
  std::printf("%5s %8s %8s  %-13s  %s\n", "frame", "max V", "mean V", "ground->sense", "presses (x mm, y mm, r mm, F N)");
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
