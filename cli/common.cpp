// The commands' shared odds and ends: the cache folder, the example sensors, frame tables.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>

#include "commands.hpp"
#include "emit/core/quote_input.hpp"
#include "emit/jobs/simulate_job.hpp"
#include "emit/model/operator_cache.hpp"

namespace emit::cli {

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

/// The realistic sheet's summary, for the user to compare a calibration with.
void print_realistic_sheet(const RealisticSheet& sheet, const std::string& path) {
  std::fprintf(stderr,
               "realistic sheet: Rs x %.4f (%.1f ohm/sq), field x %.3f to x %.3f, drive %.4f V, blur %.2f mm\n"
               "realistic sheet: electrode shifts %+.3f to %+.3f mm, series resistance %.1f to %.1f ohm; all in %s\n",
               sheet.sheet_scale, sheet.twin_sensor.sheet_resistance_ohm_per_sq, sheet.field_min_factor,
               sheet.field_max_factor, sheet.drive_voltage_V, sheet.blur_mm,
               *std::min_element(sheet.shift_mm.begin(), sheet.shift_mm.end()),
               *std::max_element(sheet.shift_mm.begin(), sheet.shift_mm.end()),
               *std::min_element(sheet.series_ohm.begin(), sheet.series_ohm.end()),
               *std::max_element(sheet.series_ohm.begin(), sheet.series_ohm.end()), path.c_str());
}

void print_simulate_report(const SimulateJob& job, const SimulateReport& r, bool table) {
  std::fprintf(stderr, "twin mesh: %lld triangles, %lld nodes, min angle %.1f deg\n",
               static_cast<long long>(r.twin_mesh.triangle_count), static_cast<long long>(r.twin_mesh.node_count),
               r.twin_mesh.min_angle_deg);
  std::printf("wrote %zu frames of %lld electrodes to %s and the presses to %s\n", r.frames.size(),
              static_cast<long long>(r.frames.empty() ? 0 : r.frames[0].rows()), job.out_path.c_str(),
              r.truth_path.c_str());
  if (table)
    for (const Frame& frame : r.frames) print_frame_table(frame);
  else print_frames_summary(r.frames, r.presses);
  if (!job.images_dir.empty()) std::printf("wrote %zu images to %s/\n", r.frames.size(), job.images_dir.c_str());
  if (r.realistic) print_realistic_sheet(*r.realistic, r.sheet_path);
}

void add_tracking_options(CLI::App* cmd, TrackerOptions& options) {
  cmd->add_option("--track-gate-mm", options.gate_mm,
                  "Tracking: a contact farther than this from a touch's predicted place is another touch")
      ->check(checked_by(&TrackerOptions::gate_mm))
      ->capture_default_str();
  cmd->add_option("--track-coast-frames", options.coast_frames,
                  "Tracking: frames a touch may go unseen before it ends (its up event)")
      ->check(non_negative_integer())
      ->capture_default_str();
  cmd->add_flag("--filter", options.filter,
                "Tracking: smooth each touch's position (a constant-velocity Kalman filter that restarts on a jump, "
                "so it does not lag a press)");
}

}  // namespace emit::cli
