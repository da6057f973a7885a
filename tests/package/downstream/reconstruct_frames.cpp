// A downstream program that reconstructs frames it was given, linking emit's core alone
// (find_package(emit COMPONENTS core)): no Boost, DDS, OpenCASCADE or libpng behind it (the
// package test checks with ldd). It reads the frames a board or `emit simulate` wrote (CSV, one
// frame of N×N volts a line), averages the untouched ones into the reference, and fits the first
// frame's contacts on the built-in sensor. Exits 0 when exactly one contact is found within 0.5 mm
// of (X, Y) (README: fit's p95 on this sheet is 0.13 mm), 1 when not, 2 on an error.
// Usage: reconstruct_frames UNTOUCHED.csv PRESSED.csv X Y
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include <emit/frame/reference.hpp>
#include <emit/pipeline/pipeline.hpp>
#include <emit/sensor/sensor_json.hpp>

namespace {

/// The user's own reader: every line of `path` a frame of N×N comma-separated volts.
std::vector<emit::Frame> read_frames(const std::string& path, int N) {
  std::ifstream in(path);
  if (!in) throw std::runtime_error(path + ": cannot read");
  std::vector<emit::Frame> frames;
  for (std::string line; std::getline(in, line);) {
    emit::Frame frame(N, N);
    std::istringstream values(line);
    std::string value;
    for (int i = 0; i < N * N; ++i) {
      if (!std::getline(values, value, ',')) throw std::runtime_error(path + ": a line of fewer than N*N values");
      frame.data()[i] = std::stod(value);
    }
    frames.push_back(frame);
  }
  return frames;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc != 5) {
    std::fprintf(stderr, "usage: reconstruct_frames UNTOUCHED.csv PRESSED.csv X Y\n");
    return 2;
  }
  const double x_mm = std::atof(argv[3]), y_mm = std::atof(argv[4]);
  try {
    const emit::Sensor sensor = emit::default_sensor();
    const int N = emit::electrode_count_of(sensor);
    const emit::Pipeline pipeline(sensor, {.method = emit::Method::fit});
    emit::Reconstructor reconstructor = pipeline.reconstructor();
    reconstructor.set_reference(emit::average_reference(read_frames(argv[1], N)));
    const std::vector<emit::Contact>& contacts = reconstructor.process(read_frames(argv[2], N).at(0));
    for (const emit::Contact& c : contacts)
      std::printf("contact at (%.2f, %.2f) mm, %.2f N\n", c.x_mm, c.y_mm, c.force_N);
    const bool found = contacts.size() == 1 && std::hypot(contacts[0].x_mm - x_mm, contacts[0].y_mm - y_mm) < 0.5;
    return found ? 0 : 1;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "reconstruct_frames: %s\n", e.what());
    return 2;
  }
}
