#pragma once
// The emit command-line tool: one file per subcommand. The CLI parses, prints and calls the
// library; it holds no maths.
#include <cstdint>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "emit/fem/forward_model.hpp"
#include "emit/sensor/sensor.hpp"
#include "emit/twin/press.hpp"

namespace emit::cli {

void add_mesh_command(CLI::App& app);
void add_simulate_command(CLI::App& app);
void add_demo_command(CLI::App& app);
void add_reconstruct_command(CLI::App& app);
void add_eval_command(CLI::App& app);
void add_calibrate_command(CLI::App& app);
void add_bench_command(CLI::App& app);
void add_live_command(CLI::App& app);

/// What `emit live` is asked to do (command_live.cpp); `emit demo` runs it too.
struct LiveArgs {
  std::string source = "sim", serve, contacts_path, record_path, method = "fit", sensor_path, calibration_path, cache_dir;
  std::uint64_t frames = 0;
  double seconds = 0;  ///< stop after this long (0: no limit)
  double frames_per_s = 50;
  bool no_cache = false;
};
/// Reconstructs frames from args.source until Ctrl-C, args.frames or args.seconds; prints the
/// viewer's address, and frames/s and latency at the end.
void run_live(const LiveArgs& args);

/// The sensor file given with --sensor, or the built-in default sensor when empty.
Sensor sensor_from_option(const std::string& path);

/// Progress on stderr: rewritten in place on a terminal, a line every ~10 % otherwise.
class Progress {
 public:
  Progress(std::string what, int total);
  void step(int done);
  void finish();

 private:
  std::string what_;
  int total_, last_percent_ = -1;
  bool tty_;
};

/// A short table of frames: presses and the largest readings.
void print_frames_summary(const std::vector<Frame>& frames, const PressSequence& presses);
/// One frame as an N×N table of volts (rows: grounded electrode, columns: sensed electrode).
void print_frame_table(const Frame& frame);

}  // namespace emit::cli
