// emit demo: the main job on the built-in sensor. For now: simulate a few presses on the default
// 60 x 60 mm sheet, print the frames' summary and draw the sheet's potential for each.
#include <chrono>
#include <cstdio>
#include <filesystem>

#include "commands.hpp"
#include "emit/io/frames_csv.hpp"
#include "emit/io/presses_csv.hpp"
#include "emit/mesh/mesh_quality.hpp"
#include "emit/render/field_image.hpp"
#include "emit/sensor/sensor_json.hpp"
#include "emit/twin/twin.hpp"

namespace emit::cli {

namespace {

void run_demo(const std::string& out_dir) {
  const Sensor sensor = default_sensor();
  const PressSequence sequence = {
      {{30, 30, 5, 10}},                    // centre, 5 mm indenter, 10 N
      {{12, 48, 5, 5}},                     // near the top-left corner, lighter
      {{20, 20, 4, 8}, {42, 40, 6, 15}},    // two fingers
      {{45, 15, 3, 2}},                     // a small, light press
  };
  std::filesystem::create_directories(out_dir);
  std::printf("emit demo: the digital twin of %s (%d electrodes, %.1f V drive, %.0f ohm/sq)\n", sensor.name.c_str(),
              sensor.electrode_count(), sensor.drive_voltage_V, sensor.sheet_resistance_ohm_per_sq);
  const auto start = std::chrono::steady_clock::now();
  Twin twin(sensor);
  const MeshQuality q = measure_mesh_quality(twin.mesh());
  std::printf("twin mesh: %lld triangles, %lld nodes, min angle %.1f deg (meshed and assembled in %.2f s)\n",
              static_cast<long long>(q.triangle_count), static_cast<long long>(q.node_count), q.min_angle_deg,
              std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());

  std::vector<Frame> frames;
  for (std::size_t f = 0; f < sequence.size(); ++f) {
    frames.push_back(twin.frame(sequence[f]));
    std::vector<Circle> outlines;
    for (const Press& p : sequence[f]) outlines.push_back({Vector2(p.x_mm, p.y_mm), p.radius_mm});
    FieldImageOptions image;
    image.title = "frame " + std::to_string(f) + ": potential, electrode 0 grounded";
    write_png(render_field(twin.mesh(), twin.potentials(sequence[f]).col(0), outlines, image),
              out_dir + "/frame_" + std::to_string(f) + ".png");
  }
  write_frames_csv(out_dir + "/frames.csv", frames);
  write_presses_csv(out_dir + "/presses.csv", sequence);
  print_frames_summary(frames, sequence);
  std::printf("electrode potentials (V) for the centre press, electrode 0 grounded:\n ");
  for (Index m = 0; m < frames[0].cols(); ++m) std::printf(" %.4f", frames[0](0, m));
  std::printf("\nwrote %s/frames.csv, %s/presses.csv and %zu images %s/frame_*.png\n", out_dir.c_str(),
              out_dir.c_str(), sequence.size(), out_dir.c_str());
}

}  // namespace

void add_demo_command(CLI::App& app) {
  auto out_dir = std::make_shared<std::string>("emit-demo");
  CLI::App* cmd = app.add_subcommand("demo", "Simulate a few presses on the built-in 60 mm sensor and draw them");
  cmd->add_option("--out", *out_dir, "Folder for the frames, presses and images")->capture_default_str();
  cmd->callback([out_dir] { run_demo(*out_dir); });
}

}  // namespace emit::cli
